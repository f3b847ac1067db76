#pragma once
// The vertex side of fog: each vertex's fog coordinate, the eye-space distance the fragment
// stage turns into a fog factor (fragment_fog.h).
#include <span>

#include "clip_vertex.h"
#include "glrenderer/fog.h"
#include "glrenderer/matrix.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

// |z| of object-space point `p` in eye space, with the reference's order of float operations.
float fogCoordinate(const Matrix& modelview, const glm::vec4& p, FogDistance distance);

// The fog coordinate of each of `vertices`, into `out`.
void fogCoordinates(std::span<const Vertex> vertices, const Matrix& modelview, FogDistance distance,
                    std::span<float> out);

}  // namespace glrenderer
