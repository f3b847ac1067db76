#include "raster_float_methods.h"

#include <algorithm>
#include <cmath>

namespace glrenderer {
namespace {

struct Point {
    float x, y;
};

}  // namespace

void rasterizeScanline(const RasterTriangle& t, const PixelRect& rect, Framebuffer& fb, FragmentCounts& counts) {
    Point v[3] = {{t.windowX[0], t.windowY[0]}, {t.windowX[1], t.windowY[1]}, {t.windowX[2], t.windowY[2]}};
    std::sort(std::begin(v), std::end(v), [](const Point& a, const Point& b) { return a.y < b.y; });
    // The long edge v0-v2 is on one side, the two short edges on the other.
    const float longSlope = (v[2].x - v[0].x) / (v[2].y - v[0].y);
    const int firstRow = std::max(static_cast<int>(std::ceil(v[0].y - 0.5f)), std::max(t.minY, rect.minY));
    const int endRow = std::min(static_cast<int>(std::ceil(v[2].y - 0.5f)), std::min(t.maxY, rect.maxY) + 1);
    for (int row = firstRow; row < endRow; ++row) {
        const float y = static_cast<float>(row) + 0.5f;
        const Point& a = y < v[1].y ? v[0] : v[1];
        const Point& b = y < v[1].y ? v[1] : v[2];
        const float shortX = a.x + (b.x - a.x) / (b.y - a.y) * (y - a.y);
        const float longX = v[0].x + longSlope * (y - v[0].y);
        const float left = std::min(shortX, longX), right = std::max(shortX, longX);
        if (!std::isfinite(left) || !std::isfinite(right)) continue;
        const int begin = std::max(static_cast<int>(std::ceil(left - 0.5f)), std::max(t.minX, rect.minX));
        const int end = std::min(static_cast<int>(std::ceil(right - 0.5f)) - 1, std::min(t.maxX, rect.maxX));
        if (begin <= end) t.fragment.shadeSpan(row, begin, end, fb, counts);
    }
}

void rasterizeBoundingBoxFloat(const RasterTriangle& t, const PixelRect& rect, Framebuffer& fb,
                               FragmentCounts& counts) {
    const float* x = t.windowX;
    const float* y = t.windowY;
    const float area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    const float sign = area < 0.0f ? -1.0f : 1.0f;
    auto edge = [&](int i, int j, float px, float py) {
        return sign * ((x[j] - x[i]) * (py - y[i]) - (y[j] - y[i]) * (px - x[i]));
    };
    const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
    for (int row = std::max(t.minY, rect.minY); row <= std::min(t.maxY, rect.maxY); ++row) {
        const float py = static_cast<float>(row) + 0.5f;
        int runBegin = -1;
        for (int px = minX; px <= maxX + 1; ++px) {
            const float cx = static_cast<float>(px) + 0.5f;
            const bool inside =
                px <= maxX && edge(0, 1, cx, py) >= 0.0f && edge(1, 2, cx, py) >= 0.0f && edge(2, 0, cx, py) >= 0.0f;
            if (inside && runBegin < 0) runBegin = px;
            if (!inside && runBegin >= 0) {
                t.fragment.shadeSpan(row, runBegin, px - 1, fb, counts);
                runBegin = -1;
            }
        }
    }
}

void rasterizeWithSlowerMethod(const RasterTriangle& t, const PixelRect& rect, Framebuffer& fb,
                               FragmentCounts& counts) {
    switch (t.method) {
    case RasterMethod::Exact: rasterizeTriangleSpans(t, rect, fb, counts, *t.fragment.routine); break;
    case RasterMethod::ExactPerPixel: rasterizeTriangleExact(t, rect, fb, counts); break;
    case RasterMethod::Scanline: rasterizeScanline(t, rect, fb, counts); break;
    case RasterMethod::BoundingBoxFloat: rasterizeBoundingBoxFloat(t, rect, fb, counts); break;
    }
}

}  // namespace glrenderer
