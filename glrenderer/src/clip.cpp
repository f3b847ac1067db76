#include "clip.h"

#include <cmath>

namespace glrenderer {
namespace {

bool isFinite(const glm::vec4& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

}  // namespace

ClipVertex clipCrossing(const ClipVertex& a, float distanceA, const ClipVertex& b, float distanceB) {
    const bool fromA = std::fabs(distanceA) < std::fabs(distanceB) ||
                       (std::fabs(distanceA) == std::fabs(distanceB) && distanceA >= 0.0f);
    const ClipVertex& from = fromA ? a : b;
    const ClipVertex& to = fromA ? b : a;
    const float t = fromA ? distanceA / (distanceA - distanceB) : distanceB / (distanceB - distanceA);
    ClipVertex v;
    v.position = from.position + t * (to.position - from.position);
    v.color = from.color + t * (to.color - from.color);
    v.backColor = from.backColor + t * (to.backColor - from.backColor);
    v.secondaryColor = from.secondaryColor + t * (to.secondaryColor - from.secondaryColor);
    v.backSecondaryColor = from.backSecondaryColor + t * (to.backSecondaryColor - from.backSecondaryColor);
    v.fogCoord = from.fogCoord + t * (to.fogCoord - from.fogCoord);
    v.texCoord = from.texCoord + t * (to.texCoord - from.texCoord);
    return v;
}

Outcode clipOutcode(const glm::vec4& p) {
    Outcode code = 0;
    for (int plane = 0; plane < kViewVolumePlanes; ++plane) {
        // Written so that NaN lands outside.
        if (!(clipPlaneDistance(p, plane, {}) >= 0.0f)) code |= static_cast<Outcode>(1u << plane);
    }
    return code;
}

Outcode userClipOutcode(const glm::vec4& p, const UserClipPlanes& user) {
    Outcode code = 0;
    for (int plane = kViewVolumePlanes; plane < kClipPlaneCount; ++plane) {
        const bool enabled = (user.enabled >> (plane - kViewVolumePlanes) & 1u) != 0;
        if (enabled && !(clipPlaneDistance(p, plane, user) >= 0.0f)) code |= static_cast<Outcode>(1u << plane);
    }
    return code;
}

ClippedPolygon clipTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, Outcode outcodeUnion,
                            const UserClipPlanes& user) {
    ClippedPolygon polygons[2];
    polygons[0].vertices[0] = v0;
    polygons[0].vertices[1] = v1;
    polygons[0].vertices[2] = v2;
    polygons[0].source = {0, 1, 2};
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
            const ClipVertex& previous = in.vertices[static_cast<std::size_t>(i - 1)];
            const ClipVertex& vertex = in.vertices[static_cast<std::size_t>(i % in.count)];
            if (!isFinite(vertex.position)) return ClippedPolygon{};
            const float previousDistance = clipPlaneDistance(previous.position, plane, user);
            const float distance = clipPlaneDistance(vertex.position, plane, user);
            if (previousDistance >= 0.0f) {
                if (out.count == kMaxClippedVertices) return ClippedPolygon{};
                out.source[static_cast<std::size_t>(out.count)] = in.source[static_cast<std::size_t>(i - 1)];
                out.vertices[static_cast<std::size_t>(out.count++)] = previous;
            }
            if ((previousDistance >= 0.0f) != (distance >= 0.0f)) {
                if (out.count == kMaxClippedVertices) return ClippedPolygon{};
                out.source[static_cast<std::size_t>(out.count)] = kNewVertex;
                out.vertices[static_cast<std::size_t>(out.count++)] =
                    clipCrossing(previous, previousDistance, vertex, distance);
            }
        }
        current = 1 - current;
    }
    return polygons[current];
}

}  // namespace glrenderer
