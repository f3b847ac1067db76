#include "raster_triangle.h"

#include <algorithm>

#include "depth_test.h"
#include "glrenderer/color_convert.h"

namespace glrenderer {
namespace {

// Floor and ceiling of a / 256 for any sign.
std::int64_t floorToPixel(std::int64_t fixed) { return fixed >> kSubpixelBits; }
std::int64_t ceilToPixel(std::int64_t fixed) {
    return -((-fixed) >> kSubpixelBits);
}

// E(p) = (b - a) x (p - a) for a triangle oriented so that its interior is E > 0. A pixel center
// exactly on the edge belongs to the triangle only if the edge is a left edge, or a horizontal
// edge at the bottom in GL's y-up window (interior above): the reference's fill rule. The bias
// folds that rule into a sign test: inside <=> E + bias >= 0.
struct EdgeFunction {
    std::int64_t stepX, stepY, valueAtOrigin;

    EdgeFunction(const FixedPoint& a, const FixedPoint& b) {
        stepX = a.y - b.y;
        stepY = b.x - a.x;
        const bool ownsCenters = stepX > 0 || (stepX == 0 && stepY < 0);
        // Value at fixed (0, 0), biased.
        valueAtOrigin = -(stepY * a.y + stepX * a.x) + (ownsCenters ? 0 : -1);
    }
    std::int64_t at(std::int64_t px, std::int64_t py) const {
        return valueAtOrigin + stepX * (px << kSubpixelBits) + stepY * (py << kSubpixelBits);
    }
};

// The attribute planes a smooth triangle interpolates: color divided by w, 1/w, and depth.
struct Planes {
    AttributePlane color[4];
    AttributePlane invW;
    AttributePlane depth;
};

Planes buildPlanes(const SetupTriangle& t) {
    const PlaneBuilder builder(t.v[0], t.v[1], t.v[2]);
    Planes planes;
    for (int c = 0; c < 4; ++c) {
        planes.color[c] = builder.plane(t.v[0].color[c] * t.v[0].invW, t.v[1].color[c] * t.v[1].invW,
                                        t.v[2].color[c] * t.v[2].invW);
    }
    planes.invW = builder.plane(t.v[0].invW, t.v[1].invW, t.v[2].invW);
    planes.depth = builder.plane(t.v[0].z, t.v[1].z, t.v[2].z);
    return planes;
}

template <bool DepthTest, bool Smooth>
void rasterize(const SetupTriangle& t, const DrawState& state, Framebuffer& fb, Stats& stats) {
    // Orient the edges so that the interior is positive; the planes keep the original order.
    const FixedPoint& a = t.fixed[0];
    const FixedPoint& b = t.area > 0 ? t.fixed[1] : t.fixed[2];
    const FixedPoint& c = t.area > 0 ? t.fixed[2] : t.fixed[1];
    const EdgeFunction edges[3] = {EdgeFunction(a, b), EdgeFunction(b, c), EdgeFunction(c, a)};

    const std::int64_t minX = std::max<std::int64_t>(ceilToPixel(std::min({a.x, b.x, c.x})), 0);
    const std::int64_t maxX = std::min<std::int64_t>(floorToPixel(std::max({a.x, b.x, c.x})), fb.width() - 1);
    const std::int64_t minY = std::max<std::int64_t>(ceilToPixel(std::min({a.y, b.y, c.y})), 0);
    const std::int64_t maxY = std::min<std::int64_t>(floorToPixel(std::max({a.y, b.y, c.y})), fb.height() - 1);
    if (minX > maxX || minY > maxY) return;

    const Planes planes = buildPlanes(t);
    const std::uint32_t flatColor = fragmentRgba8(t.flatColor);
    const auto color = fb.color();
    const auto depth = fb.depth();
    const std::size_t width = static_cast<std::size_t>(fb.width());

    std::uint64_t fragments = 0, passed = 0;
    for (std::int64_t py = minY; py <= maxY; ++py) {
        std::int64_t e0 = edges[0].at(minX, py), e1 = edges[1].at(minX, py), e2 = edges[2].at(minX, py);
        const std::size_t row = static_cast<std::size_t>(fb.height() - 1 - py) * width;
        const float y = static_cast<float>(py);
        for (std::int64_t px = minX; px <= maxX; ++px) {
            if ((e0 | e1 | e2) >= 0) {
                ++fragments;
                const std::size_t index = row + static_cast<std::size_t>(px);
                const float x = static_cast<float>(px);
                bool pass = true;
                if constexpr (DepthTest) {
                    const std::uint32_t z = toDepth24(planes.depth.at(x, y));
                    pass = depthPasses(state.depthFunc, z, depth[index]);
                    if (pass && state.depthWrite) depth[index] = z;
                }
                if (pass) {
                    ++passed;
                    if constexpr (Smooth) {
                        const float w = 1.0f / planes.invW.at(x, y);
                        const glm::vec4 rgba(planes.color[0].at(x, y) * w, planes.color[1].at(x, y) * w,
                                             planes.color[2].at(x, y) * w, planes.color[3].at(x, y) * w);
                        color[index] = fragmentRgba8(rgba);
                    } else {
                        color[index] = flatColor;
                    }
                }
            }
            e0 += edges[0].stepX << kSubpixelBits;
            e1 += edges[1].stepX << kSubpixelBits;
            e2 += edges[2].stepX << kSubpixelBits;
        }
    }
    stats.fragments += fragments;
    stats.fragmentsPassed += passed;
    stats.pixelsWritten += passed;
}

}  // namespace

void rasterizeTriangleExact(const SetupTriangle& triangle, const DrawState& state,
                            Framebuffer& framebuffer, Stats& stats) {
    const bool smooth = state.shadeModel == ShadeModel::Smooth;
    if (state.depthTest) {
        if (smooth) rasterize<true, true>(triangle, state, framebuffer, stats);
        else rasterize<true, false>(triangle, state, framebuffer, stats);
    } else {
        if (smooth) rasterize<false, true>(triangle, state, framebuffer, stats);
        else rasterize<false, false>(triangle, state, framebuffer, stats);
    }
}

}  // namespace glrenderer
