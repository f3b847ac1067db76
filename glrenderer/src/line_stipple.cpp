#include "line_stipple.h"

#include <cmath>

namespace glrenderer {
namespace {

// The longest line measured: a window coordinate beyond 2^22 pixels is refused by the line
// rasterizer anyway.
constexpr float kLongestLine = 1 << 23;

// a + t * (b - a), a multiply and an add (the reference's C, compiled without FMA).
float lerp(float a, float b, float t) { return a + t * (b - a); }

}  // namespace

float LineStippler::majorLength(const WindowVertex& a, const WindowVertex& b) {
    const float dx = a.x > b.x ? a.x - b.x : b.x - a.x;
    const float dy = a.y > b.y ? a.y - b.y : b.y - a.y;
    return dx > dy ? dx : dy;
}

float LineStippler::euclideanLength(const WindowVertex& a, const WindowVertex& b) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    return std::sqrt(dx * dx + dy * dy);
}

int LineStippler::wholePixels(float length) {
    if (!(length <= kLongestLine)) return 0;  // NaN, infinite or huge
    return static_cast<int>(std::ceil(length));
}

WindowVertex LineStippler::interpolate(const WindowVertex& a, const WindowVertex& b, float t) {
    WindowVertex v;
    v.x = lerp(a.x, b.x, t), v.y = lerp(a.y, b.y, t), v.z = lerp(a.z, b.z, t), v.invW = lerp(a.invW, b.invW, t);
    for (int c = 0; c < 4; ++c) {
        v.color[c] = lerp(a.color[c], b.color[c], t);
        v.texCoord[c] = lerp(a.texCoord[c], b.texCoord[c], t);
    }
    for (int c = 0; c < 3; ++c) v.secondaryColor[c] = lerp(a.secondaryColor[c], b.secondaryColor[c], t);
    v.fogCoord = lerp(a.fogCoord, b.fogCoord, t);
    return v;
}

}  // namespace glrenderer
