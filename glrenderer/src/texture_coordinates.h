#pragma once
#include <span>

#include <glm/vec4.hpp>

#include "glrenderer/texture.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

// The vertices' texture coordinates as the fragment stage interpolates them: each times the
// texture matrix when it is not the identity, in the reference's arithmetic.
void textureCoordinates(std::span<const Vertex> vertices, const TextureState& texture, std::span<glm::vec4> out);

}  // namespace glrenderer
