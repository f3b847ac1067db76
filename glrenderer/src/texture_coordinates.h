#pragma once
#include <span>

#include <glm/vec4.hpp>

#include "glrenderer/texture.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

// The vertices' texture coordinates as the fragment stage interpolates them: generated
// (glTexGen) where enabled, then times the texture matrix when it is not the identity, in the
// reference's arithmetic (Mesa's fixed-function vertex program, every MAD unfused).
void textureCoordinates(std::span<const Vertex> vertices, const TextureState& texture, const Matrix& modelview,
                        std::span<glm::vec4> out);

}  // namespace glrenderer
