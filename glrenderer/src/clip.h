#pragma once
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

#include "clip_vertex.h"

namespace glrenderer {

inline constexpr int kClipPlaneCount = 6;

// Signed distance of a clip-space position to view-volume plane `plane` (>= 0 inside), in the
// reference's order: x <= w, x >= -w, y <= w, y >= -w, z >= -w (near), z <= w (far).
inline float clipPlaneDistance(const glm::vec4& p, int plane) {
    switch (plane) {
    case 0: return p.w - p.x;
    case 1: return p.x + p.w;
    case 2: return p.w - p.y;
    case 3: return p.y + p.w;
    case 4: return p.z + p.w;
    default: return p.w - p.z;
    }
}

// Bit `plane` set for each plane the position is outside of. A non-finite position is outside all.
std::uint8_t clipOutcode(const glm::vec4& position);

// Where the edge a-b crosses a plane, given both ends' distances to it (of opposite signs):
// interpolated in clip space from the end nearer the plane (the inside one on a tie), as the
// reference does.
ClipVertex clipCrossing(const ClipVertex& a, float distanceA, const ClipVertex& b, float distanceB);
// A triangle clipped by six planes gains at most one vertex per plane.
inline constexpr int kMaxClippedVertices = 3 + kClipPlaneCount;

struct ClippedPolygon {
    std::array<ClipVertex, kMaxClippedVertices> vertices;
    // Which input vertex (0, 1, 2) each one is, or kNewVertex for one made on a clip plane: the
    // reference keeps the input vertices' window positions from its vertex stage.
    std::array<int, kMaxClippedVertices> source;
    int count = 0;
};
inline constexpr int kNewVertex = -1;

// Clips triangle (v0, v1, v2) in clip space against the view volume (Sutherland-Hodgman, plane
// by plane in the reference's order). The polygon starts at v0 and is drawn as the fan
// (p[i-1], p[i], p[0]), as the reference emits it. Fewer than three vertices: nothing is left.
ClippedPolygon clipTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                            std::uint8_t outcodeUnion);

}  // namespace glrenderer
