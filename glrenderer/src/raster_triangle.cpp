#include "raster_triangle.h"

#include <algorithm>

#include "depth_test.h"
#include "glrenderer/color_convert.h"

namespace glrenderer {
namespace {

// Floor and ceiling of a fixed-point value in whole pixels, for any sign.
std::int64_t floorToPixel(std::int64_t fixed) { return fixed >> kSubpixelBits; }
std::int64_t ceilToPixel(std::int64_t fixed) { return -((-fixed) >> kSubpixelBits); }

template <bool DepthTest, bool Smooth>
void rasterize(const RasterTriangle& t, const PixelRect& rect, Framebuffer& fb, FragmentCounts& counts) {
    const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
    const int minY = std::max(t.minY, rect.minY), maxY = std::min(t.maxY, rect.maxY);
    if (minX > maxX || minY > maxY) return;

    const auto color = fb.color();
    const auto depth = fb.depth();
    const std::size_t width = static_cast<std::size_t>(fb.width());
    std::uint64_t fragments = 0, passed = 0;
    for (int py = minY; py <= maxY; ++py) {
        std::int64_t e0 = t.edges[0].at(minX, py), e1 = t.edges[1].at(minX, py), e2 = t.edges[2].at(minX, py);
        const std::size_t row = static_cast<std::size_t>(fb.height() - 1 - py) * width;
        const float y = static_cast<float>(py);
        for (int px = minX; px <= maxX; ++px, e0 += t.edges[0].stepX, e1 += t.edges[1].stepX,
                 e2 += t.edges[2].stepX) {
            if ((e0 | e1 | e2) < 0) continue;
            ++fragments;
            const std::size_t index = row + static_cast<std::size_t>(px);
            const float x = static_cast<float>(px);
            if constexpr (DepthTest) {
                const std::uint32_t z = toDepth24(t.depth.at(x, y));
                if (!depthPasses(t.state.depthFunc, z, depth[index])) continue;
                if (t.state.depthWrite) depth[index] = z;
            }
            ++passed;
            if constexpr (Smooth) {
                const float w = 1.0f / t.invW.at(x, y);
                color[index] = fragmentRgba8({t.color[0].at(x, y) * w, t.color[1].at(x, y) * w,
                                              t.color[2].at(x, y) * w, t.color[3].at(x, y) * w});
            } else {
                color[index] = t.flatColor;
            }
        }
    }
    counts.fragments += fragments;
    counts.passed += passed;
}

}  // namespace

EdgeFunction::EdgeFunction(const FixedPoint& a, const FixedPoint& b) {
    const std::int64_t dx = a.y - b.y;  // dE per fixed-point unit of x
    const std::int64_t dy = b.x - a.x;
    const bool ownsCenters = dx > 0 || (dx == 0 && dy < 0);
    stepX = dx << kSubpixelBits;
    stepY = dy << kSubpixelBits;
    valueAtOrigin = -(dy * a.y + dx * a.x) + (ownsCenters ? 0 : -1);
}

bool prepareTriangle(const SetupTriangle& t, const DrawState& state, const Methods& methods,
                     int width, int height, RasterTriangle& out) {
    // Orient the edges so that the interior is positive.
    const FixedPoint& a = t.fixed[0];
    const FixedPoint& b = t.area > 0 ? t.fixed[1] : t.fixed[2];
    const FixedPoint& c = t.area > 0 ? t.fixed[2] : t.fixed[1];
    std::int64_t minX = ceilToPixel(std::min({a.x, b.x, c.x})), maxX = floorToPixel(std::max({a.x, b.x, c.x}));
    std::int64_t minY = ceilToPixel(std::min({a.y, b.y, c.y})), maxY = floorToPixel(std::max({a.y, b.y, c.y}));
    out.method = methods.raster;
    out.meanDepth = (t.v[0].z + t.v[1].z + t.v[2].z) / 3.0f;
    if (methods.raster == RasterMethod::Scanline || methods.raster == RasterMethod::BoundingBoxFloat) {
        // Float methods may reach a pixel past the snapped bounds.
        --minX, ++maxX, --minY, ++maxY;
        for (int i = 0; i < 3; ++i) out.windowX[i] = t.v[i].x, out.windowY[i] = t.v[i].y;
    }
    out.minX = static_cast<int>(std::max<std::int64_t>(minX, 0));
    out.maxX = static_cast<int>(std::min<std::int64_t>(maxX, width - 1));
    out.minY = static_cast<int>(std::max<std::int64_t>(minY, 0));
    out.maxY = static_cast<int>(std::min<std::int64_t>(maxY, height - 1));
    if (out.minX > out.maxX || out.minY > out.maxY) return false;
    out.edges[0] = EdgeFunction(a, b);
    out.edges[1] = EdgeFunction(b, c);
    out.edges[2] = EdgeFunction(c, a);

    // The painter's sort replaces the depth buffer: it orders whole triangles instead.
    const bool depthTest = state.depthTest && methods.hiddenSurface != HiddenSurface::PaintersSort;
    out.state = {depthTest, state.depthFunc, state.depthWrite, state.shadeModel == ShadeModel::Smooth};
    const bool perspective = methods.interpolation == Interpolation::PerspectiveCorrect;
    // Flat shading is a constant in the reference, not an interpolation of equal colors.
    if (!out.state.smooth) {
        out.flatColor = fragmentRgba8(t.flatColor);
        if (!out.state.depthTest) return true;
    }
    // The reference sets up planes only for triangles counter-clockwise in its y-down view; one
    // clockwise in GL's window (area > 0 here) is set up as (v1, v0, v2), keeping the provoking
    // vertex last. The planes' last bits follow that order.
    const bool clockwise = t.area > 0;
    const WindowVertex& v0 = clockwise ? t.v[1] : t.v[0];
    const WindowVertex& v1 = clockwise ? t.v[0] : t.v[1];
    const WindowVertex& v2 = t.v[2];
    const PlaneBuilder planes(v0, v1, v2);
    if (out.state.smooth && !perspective) {
        for (int i = 0; i < 4; ++i) out.color[i] = planes.plane(v0.color[i], v1.color[i], v2.color[i]);
        out.invW = {1.0f, 0.0f, 0.0f};
    } else if (out.state.smooth) {
        for (int i = 0; i < 4; ++i) {
            out.color[i] = planes.plane(v0.color[i] * v0.invW, v1.color[i] * v1.invW, v2.color[i] * v2.invW);
        }
        out.invW = planes.plane(v0.invW, v1.invW, v2.invW);
    }
    // The plane (1, 0, 0) is 1 at every pixel, and x * 1 is x for every float x.
    const bool constantOne = out.invW.a0 == 1.0f && out.invW.dadx == 0.0f && out.invW.dady == 0.0f;
    out.state.perspective = out.state.smooth && !constantOne;
    if (out.state.depthTest) out.depth = planes.plane(v0.z, v1.z, v2.z);
    return true;
}

void rasterizeTriangleExact(const RasterTriangle& triangle, const PixelRect& rect,
                            Framebuffer& framebuffer, FragmentCounts& counts) {
    if (triangle.state.depthTest) {
        if (triangle.state.smooth) rasterize<true, true>(triangle, rect, framebuffer, counts);
        else rasterize<true, false>(triangle, rect, framebuffer, counts);
    } else {
        if (triangle.state.smooth) rasterize<false, true>(triangle, rect, framebuffer, counts);
        else rasterize<false, false>(triangle, rect, framebuffer, counts);
    }
}

}  // namespace glrenderer
