#pragma once
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

#include "glrenderer/vertex.h"

namespace glrenderer {

// One bit per view-volume plane a clip-space position is outside of: x >= -w, x <= w, y >= -w,
// y <= w, z >= -w, z <= w, in the reference's plane order. A non-finite position is outside all.
std::uint8_t clipOutcode(const glm::vec4& position);

inline constexpr int kClipPlaneCount = 6;
// A triangle clipped by six planes gains at most one vertex per plane.
inline constexpr int kMaxClippedVertices = 3 + kClipPlaneCount;

struct ClippedPolygon {
    std::array<Vertex, kMaxClippedVertices> vertices;
    int count = 0;
};

// Clips triangle (v0, v1, v2) in clip space against the view volume (Sutherland-Hodgman, new
// vertices interpolated in clip space). The polygon starts at the provoking vertex v2, so that
// the fan (p[i-1], p[i], p[0]) keeps it last, as the reference emits it. Fewer than three
// vertices means nothing is left.
ClippedPolygon clipTriangle(const Vertex& v0, const Vertex& v1, const Vertex& v2,
                            std::uint8_t outcodeUnion);

}  // namespace glrenderer
