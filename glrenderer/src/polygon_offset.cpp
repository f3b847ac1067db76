#include "polygon_offset.h"

#include <algorithm>
#include <cmath>

namespace glrenderer {
namespace {

// [0, 1], NaN to 0.
float saturate(float z) { return z > 0.0f ? std::min(z, 1.0f) : 0.0f; }

// The offset for slopes dzdx, dzdy: units first, as both stages add.
float depthOffset(const PolygonOffset& offset, float dzdx, float dzdy) {
    // The units in steps of the 24-bit depth buffer, times 2 as the reference scales them
    // (measured: one unit moves depth by two steps).
    constexpr double kResolution = 1.0 / 16777215.0;
    const auto units = static_cast<float>(offset.units * kResolution * 2.0);
    return units + std::max(std::fabs(dzdx), std::fabs(dzdy)) * offset.factor;
}

}  // namespace

float setupDepthOffset(const PolygonOffset& offset, const WindowVertex& v0, const WindowVertex& v1,
                       const WindowVertex& v2) {
    // The slopes through cross(v0 - v1, v2 - v0), over setup's determinant.
    const float dx01 = v0.x - v1.x, dy01 = v0.y - v1.y, dz01 = v0.z - v1.z;
    const float dx20 = v2.x - v0.x, dy20 = v2.y - v0.y, dz20 = v2.z - v0.z;
    const float inverseDeterminant = 1.0f / (dx01 * dy20 - dy01 * dx20);
    return depthOffset(offset, (dy01 * dz20 - dz01 * dy20) * inverseDeterminant,
                       (dz01 * dx20 - dx01 * dz20) * inverseDeterminant);
}

void offsetInDrawModule(const PolygonOffset& offset, WindowVertex& v0, WindowVertex& v1, WindowVertex& v2) {
    // The slopes through cross(e, f), e = v0 - v2, f = v1 - v2, over the draw module's determinant.
    const float ex = v0.x - v2.x, ey = v0.y - v2.y, ez = v0.z - v2.z;
    const float fx = v1.x - v2.x, fy = v1.y - v2.y, fz = v1.z - v2.z;
    const float inverseDeterminant = 1.0f / (ex * fy - ey * fx);
    const float z =
        depthOffset(offset, (ey * fz - ez * fy) * inverseDeterminant, (ez * fx - ex * fz) * inverseDeterminant);
    v0.z = saturate(v0.z + z);
    v1.z = saturate(v1.z + z);
    v2.z = saturate(v2.z + z);
}

}  // namespace glrenderer
