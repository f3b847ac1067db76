#include "clip.h"

#include <cmath>

namespace glrenderer {
namespace {

// Signed distance to plane `plane` (>= 0 inside), in the reference's plane order.
float planeDistance(const glm::vec4& p, int plane) {
    switch (plane) {
    case 0: return p.x + p.w;
    case 1: return p.w - p.x;
    case 2: return p.y + p.w;
    case 3: return p.w - p.y;
    case 4: return p.z + p.w;
    default: return p.w - p.z;
    }
}

// The point at parameter t from `outside` towards `inside`, position and color alike.
Vertex interpolate(const Vertex& outside, const Vertex& inside, float t) {
    Vertex v;
    v.position = outside.position + t * (inside.position - outside.position);
    v.color = outside.color + t * (inside.color - outside.color);
    v.edgeFlag = true;
    return v;
}

bool isFinite(const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

}  // namespace

std::uint8_t clipOutcode(const glm::vec4& p) {
    std::uint8_t code = 0;
    for (int plane = 0; plane < kClipPlaneCount; ++plane) {
        // Written so that NaN lands outside.
        if (!(planeDistance(p, plane) >= 0.0f)) code |= static_cast<std::uint8_t>(1u << plane);
    }
    return code;
}

ClippedPolygon clipTriangle(const Vertex& v0, const Vertex& v1, const Vertex& v2,
                            std::uint8_t outcodeUnion) {
    ClippedPolygon polygons[2];
    polygons[0].vertices[0] = v2;
    polygons[0].vertices[1] = v0;
    polygons[0].vertices[2] = v1;
    polygons[0].count = 3;
    int current = 0;
    for (int plane = 0; plane < kClipPlaneCount; ++plane) {
        if (!(outcodeUnion & (1u << plane))) continue;
        const ClippedPolygon& in = polygons[current];
        ClippedPolygon& out = polygons[1 - current];
        out.count = 0;
        if (in.count < 3) return in;
        // Walk the edges (p[i-1], p[i]) for i = 1..n with p[n] = p[0], so that the output
        // starts where the input did: the fan's first vertex depends on it.
        for (int i = 1; i <= in.count; ++i) {
            const Vertex& previous = in.vertices[static_cast<std::size_t>(i - 1)];
            const Vertex& vertex = in.vertices[static_cast<std::size_t>(i % in.count)];
            if (!isFinite(vertex.position)) return ClippedPolygon{};
            const float previousDistance = planeDistance(previous.position, plane);
            const float distance = planeDistance(vertex.position, plane);
            if (previousDistance >= 0.0f) out.vertices[static_cast<std::size_t>(out.count++)] = previous;
            if ((previousDistance >= 0.0f) != (distance >= 0.0f)) {
                out.vertices[static_cast<std::size_t>(out.count++)] = distance < 0.0f
                    ? interpolate(vertex, previous, distance / (distance - previousDistance))
                    : interpolate(previous, vertex, previousDistance / (previousDistance - distance));
            }
        }
        current = 1 - current;
    }
    return polygons[current];
}

}  // namespace glrenderer
