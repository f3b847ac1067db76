#include <algorithm>
#include <cmath>

#include "pixel_rect.h"
#include "smooth_primitives.h"
#include "smooth_triangle.h"

namespace glrenderer {
namespace {

constexpr float kMaxSmoothPointSize = 255.0f;

// The reference's NIR coverage of a smooth point: aa = (s, t, k, 1).
Coverage pointCoverage(const glm::vec4& aa) {
    const float d = aa.x * aa.x + aa.y * aa.y;
    const float one = aa.w;
    if (one < d) return {false, 0.0f};
    const float factor = (1.0f / (one - aa.z)) * (one - d);
    return {true, aa.z >= d ? factor : one};
}

}  // namespace

void queueSmoothPoint(const WindowVertex& point, const DrawState& state, const FragmentChoice& fragments,
                      const PixelRect& drawable, PrimitiveQueue& queue) {
    if (!(state.pointSize >= 0.0f)) return;  // NaN: the reference's quad has no area
    const float size = std::min(state.pointSize, kMaxSmoothPointSize);
    const float radius = size <= 2.0f ? 1.0f : 0.5f * size;
    float k = 1.0f / radius;
    k = 1.0f - 2.0f * k + k * k;
    SmoothVertex v[4];
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; ++i) {
        v[i].v = point;
        v[i].v.x = corners[i][0] < 0 ? point.x - radius : point.x + radius;
        v[i].v.y = corners[i][1] < 0 ? point.y - radius : point.y + radius;
        v[i].aa = {corners[i][0], corners[i][1], k, 1.0f};
    }
    const SmoothShading shading = smoothShading(state);
    queueSmoothTriangle(v[0], v[1], v[2], shading, point.color, pointCoverage, fragments, drawable, queue);
    queueSmoothTriangle(v[0], v[2], v[3], shading, point.color, pointCoverage, fragments, drawable, queue);
}

}  // namespace glrenderer
