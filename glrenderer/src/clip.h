#pragma once
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

#include "glrenderer/draw_state.h"
#include "clip_vertex.h"

namespace glrenderer {

// The planes a primitive is clipped by, in the reference's order: the view volume's six, then
// the program's (glClipPlane).
inline constexpr int kViewVolumePlanes = 6;
inline constexpr int kClipPlaneCount = kViewVolumePlanes + 8;
// Bit p set: the position is outside plane p.
using Outcode = std::uint16_t;

// Signed distance of a clip-space position to plane `plane` (>= 0 inside): the view volume's
// x <= w, x >= -w, y <= w, y >= -w, z >= -w (near), z <= w (far), then the program's planes
// (a dot product summed left to right, as the reference's clipper and cliptest compute it).
inline float clipPlaneDistance(const glm::vec4& p, int plane, const UserClipPlanes& user) {
    if (plane >= kViewVolumePlanes) {
        const glm::vec4& c = user.planes[static_cast<std::size_t>(plane - kViewVolumePlanes)];
        return p.x * c.x + p.y * c.y + p.z * c.z + p.w * c.w;
    }
    switch (plane) {
    case 0: return p.w - p.x;
    case 1: return p.x + p.w;
    case 2: return p.w - p.y;
    case 3: return p.y + p.w;
    case 4: return p.z + p.w;
    default: return p.w - p.z;
    }
}

// Bit `plane` set for each view-volume plane the position is outside of. A non-finite position
// is outside all.
Outcode clipOutcode(const glm::vec4& position);
// The bits of the program's enabled planes the position is outside of: a negative distance, or
// NaN (llvmpipe's generated cliptest compares unordered).
Outcode userClipOutcode(const glm::vec4& position, const UserClipPlanes& user);
inline Outcode clipOutcode(const glm::vec4& position, const UserClipPlanes& user) {
    return user.enabled ? clipOutcode(position) | userClipOutcode(position, user) : clipOutcode(position);
}

// Where the edge a-b crosses a plane, given both ends' distances to it (of opposite signs):
// interpolated in clip space from the end nearer the plane (the inside one on a tie), as the
// reference does.
ClipVertex clipCrossing(const ClipVertex& a, float distanceA, const ClipVertex& b, float distanceB);
// A convex polygon gains at most one vertex per clip plane, but rounding can make a nearly
// degenerate one cross a plane more than twice; the reference's clipper has room for
// 2 * 14 + 1 vertices and drops a triangle that would need more (draw_pipe_clip.c).
inline constexpr int kMaxClippedVertices = 2 * kClipPlaneCount + 1;

struct ClippedPolygon {
    std::array<ClipVertex, kMaxClippedVertices> vertices;
    // Which input vertex (0, 1, 2) each one is, or kNewVertex for one made on a clip plane: the
    // reference keeps the input vertices' window positions from its vertex stage.
    std::array<int, kMaxClippedVertices> source;
    int count = 0;
};
inline constexpr int kNewVertex = -1;

// Clips triangle (v0, v1, v2) in clip space against the planes of `outcodeUnion`
// (Sutherland-Hodgman, plane by plane in the reference's order). The polygon starts at v0 and is drawn as the fan
// (p[i-1], p[i], p[0]), as the reference emits it. Fewer than three vertices: nothing is left.
ClippedPolygon clipTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, Outcode outcodeUnion,
                            const UserClipPlanes& user);

}  // namespace glrenderer
