#include "raster_point.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "depth_test.h"
#include "glrenderer/color_convert.h"
#include "round_half_away.h"
#include "triangle_setup.h"

namespace glrenderer {
namespace {

constexpr float kMaxPointCoordinate = 1 << 22;
// The reference's maximum point size.
constexpr float kMaxPointSize = 255.0f;

struct PixelBox {
    std::int64_t x0, y0, x1, y1;  // inclusive
};

// The covered pixels in internal (y-down) rows. The snapped y is lowered by one 1/256 step
// first (the reference's bottom-edge adjustment): centers exactly on a pixel boundary go down
// in GL coordinates. Size 1 takes the pixel holding the center, odd sizes grow around it, even
// sizes around the nearest pixel corner. Sizes round to an integer with halves going down.
PixelBox pointBox(const WindowVertex& v, float size) {
    const std::int64_t x = toFixedHalfAway(v.x);
    const std::int64_t y = toFixedHalfAway(v.y) - 1;
    const std::int64_t rounded = (toFixedHalfAway(size) + (1 << kSubpixelBits) / 2 - 1) >> kSubpixelBits;
    const std::int64_t s = std::max<std::int64_t>(rounded, 1);
    std::int64_t x0, y0;
    if (s % 2 == 1) {
        x0 = (x >> kSubpixelBits) - (s - 1) / 2;
        y0 = (y >> kSubpixelBits) - (s - 1) / 2;
    } else {
        x0 = ((x + 128) >> kSubpixelBits) - s / 2;
        y0 = ((y + 128) >> kSubpixelBits) - s / 2;
    }
    return {x0, y0, x0 + s - 1, y0 + s - 1};
}

template <bool DepthTest>
void fillBox(const PixelBox& box, std::uint32_t rgba, std::uint32_t z, const DrawState& state,
             Framebuffer& fb, Stats& stats) {
    const auto color = fb.color();
    const auto depth = fb.depth();
    const std::size_t width = static_cast<std::size_t>(fb.width());
    std::uint64_t fragments = 0, passed = 0;
    for (std::int64_t py = box.y0; py <= box.y1; ++py) {
        const std::size_t row = static_cast<std::size_t>(fb.height() - 1 - py) * width;
        for (std::int64_t px = box.x0; px <= box.x1; ++px) {
            ++fragments;
            const std::size_t index = row + static_cast<std::size_t>(px);
            if constexpr (DepthTest) {
                if (!depthPasses(state.depthFunc, z, depth[index])) continue;
                if (state.depthWrite) depth[index] = z;
            }
            ++passed;
            color[index] = rgba;
        }
    }
    stats.fragments += fragments;
    stats.fragmentsPassed += passed;
    stats.pixelsWritten += passed;
}

}  // namespace

void rasterizePoint(const WindowVertex& point, const DrawState& state, Framebuffer& framebuffer,
                    Stats& stats) {
    if (!(std::fabs(point.x) < kMaxPointCoordinate && std::fabs(point.y) < kMaxPointCoordinate &&
          std::isfinite(point.z) && std::isfinite(point.invW))) {
        return;
    }
    const float size = state.pointSize > 1.0f ? std::min(state.pointSize, kMaxPointSize) : 1.0f;  // NaN: 1
    PixelBox box = pointBox(point, size);
    box.x0 = std::max<std::int64_t>(box.x0, 0);
    box.y0 = std::max<std::int64_t>(box.y0, 0);
    box.x1 = std::min<std::int64_t>(box.x1, framebuffer.width() - 1);
    box.y1 = std::min<std::int64_t>(box.y1, framebuffer.height() - 1);
    if (box.x0 > box.x1 || box.y0 > box.y1) return;

    // The color is set up divided by w and multiplied back per fragment, as for any
    // perspective-correct attribute of the reference; flat colors are used as they are.
    glm::vec4 c = point.color;
    if (state.shadeModel == ShadeModel::Smooth) c = c * point.invW * (1.0f / point.invW);
    const std::uint32_t rgba = fragmentRgba8(c);
    if (state.depthTest) fillBox<true>(box, rgba, toDepth24(point.z), state, framebuffer, stats);
    else fillBox<false>(box, rgba, 0, state, framebuffer, stats);
}

}  // namespace glrenderer
