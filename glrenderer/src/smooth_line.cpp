#include <algorithm>
#include <cmath>

#include "pixel_rect.h"
#include "smooth_primitives.h"
#include "smooth_triangle.h"

namespace glrenderer {
namespace {

constexpr float kMaxSmoothLineWidth = 255.0f;

float saturate(float v) { return std::clamp(v, 0.0f, 1.0f); }

// The reference's NIR coverage of a smooth line: aa = (across, half-width, along, half-length).
Coverage lineCoverage(const glm::vec4& aa) {
    const float across = saturate(aa.y - std::fabs(aa.x));
    const float along = saturate(aa.w - std::fabs(aa.z));
    return {true, across * along};
}

}  // namespace

void queueSmoothLine(const WindowVertex& start, const WindowVertex& end, const glm::vec4& flatColor,
                     const DrawState& state, const FragmentChoice& fragments, const PixelRect& drawable,
                     PrimitiveQueue& queue) {
    if (!(state.lineWidth >= 0.0f)) return;  // NaN: the reference's quad has no area
    const float width = std::min(state.lineWidth, kMaxSmoothLineWidth);
    const float halfWidth = width <= 1.0f ? 1.0f : 0.5f * width + 0.5f;
    const float dx = end.x - start.x;
    const float dy = end.y - start.y;
    const float angle = std::atan2(dy, dx);
    const float cosA = std::cos(angle), sinA = std::sin(angle);
    float halfLength = 0.5f * std::sqrt(dx * dx + dy * dy);
    // Under half a pixel the stage doubles the half length instead, so that a line of length
    // (near) 0 gets alpha (near) 0.
    halfLength = halfLength < 0.5f ? 2.0f * halfLength : halfLength + 0.5f;
    const float tl = 0.5f, tw = halfWidth;
    SmoothVertex v[4];
    // Corners: 0 and 1 at the start (sides +tw and -tw), 2 and 3 at the end.
    for (int i = 0; i < 4; ++i) {
        const float l = i < 2 ? -tl : tl;
        const float w = i % 2 == 0 ? tw : -tw;
        v[i].v = i < 2 ? start : end;
        v[i].v.x += l * cosA - w * sinA;
        v[i].v.y += l * sinA + w * cosA;
        v[i].aa = {i % 2 == 0 ? -halfWidth : halfWidth, halfWidth, i < 2 ? -halfLength : halfLength, halfLength};
    }
    const SmoothShading shading = smoothShading(state);
    if (shading.flat) {
        for (SmoothVertex& s : v) s.v.color = flatColor;
    }
    queueSmoothTriangle(v[2], v[1], v[0], shading, flatColor, lineCoverage, fragments, drawable, queue);
    queueSmoothTriangle(v[3], v[1], v[2], shading, flatColor, lineCoverage, fragments, drawable, queue);
}

}  // namespace glrenderer
