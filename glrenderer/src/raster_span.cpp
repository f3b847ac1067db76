#include "raster_span.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "cpu_features.h"
#include "depth_test.h"
#include "glrenderer/color_convert.h"

namespace glrenderer {
namespace {

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {  // b > 0
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
std::int64_t ceilDiv(std::int64_t a, std::int64_t b) { return -floorDiv(-a, b); }  // b > 0

}  // namespace

Span coveredSpan(const RasterTriangle& t, int row, int minX, int maxX) {
    std::int64_t begin = minX, end = maxX;
    for (const EdgeFunction& edge : t.edges) {
        // Inside where value + stepX * x >= 0.
        const std::int64_t value = edge.valueAtOrigin + edge.stepY * row;
        if (edge.stepX > 0) begin = std::max(begin, ceilDiv(-value, edge.stepX));
        else if (edge.stepX < 0) end = std::min(end, floorDiv(value, -edge.stepX));
        else if (value < 0) return {1, 0};
    }
    if (begin > end) return {1, 0};
    return {static_cast<int>(begin), static_cast<int>(end)};
}

void shadeSpanScalar(const RasterTriangle& t, int row, int begin, int end, Framebuffer& fb,
                     FragmentCounts& counts) {
    const std::size_t offset = static_cast<std::size_t>(fb.height() - 1 - row) * static_cast<std::size_t>(fb.width());
    std::uint32_t* color = fb.color().data() + offset;
    std::uint32_t* depth = fb.depth().data() + offset;
    const float y = static_cast<float>(row);
    std::uint64_t passed = 0;
    for (int px = begin; px <= end; ++px) {
        const float x = static_cast<float>(px);
        if (t.state.depthTest) {
            const std::uint32_t z = toDepth24(t.depth.at(x, y));
            if (!depthPasses(t.state.depthFunc, z, depth[px])) continue;
            if (t.state.depthWrite) depth[px] = z;
        }
        ++passed;
        if (t.state.smooth && t.state.perspective) {
            const float w = 1.0f / t.invW.at(x, y);
            color[px] = fragmentRgba8({t.color[0].at(x, y) * w, t.color[1].at(x, y) * w,
                                       t.color[2].at(x, y) * w, t.color[3].at(x, y) * w});
        } else if (t.state.smooth) {
            color[px] = fragmentRgba8({t.color[0].at(x, y), t.color[1].at(x, y), t.color[2].at(x, y),
                                       t.color[3].at(x, y)});
        } else {
            color[px] = t.flatColor;
        }
    }
    counts.fragments += static_cast<std::uint64_t>(end - begin + 1);
    counts.passed += passed;
}

void rasterizeTriangleSpans(const RasterTriangle& t, const PixelRect& rect, Framebuffer& fb,
                            FragmentCounts& counts, const ExactKernels& kernels) {
    const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
    const int minY = std::max(t.minY, rect.minY), maxY = std::min(t.maxY, rect.maxY);
    if (minX > maxX || minY > maxY) return;
    if (kernels.narrow && kernels.narrow(t, {minX, maxX, minY, maxY}, fb, counts)) return;
    // The edge functions are linear: if the four corners of the area are inside an edge, all of
    // it is; if they are all outside one edge, none of it is. A tile a large triangle covers
    // whole then needs no span search, and one it misses needs nothing. (Not worth testing for
    // a few rows.)
    constexpr int kCornerTestRows = 8;
    bool coveredWhole = false;
    if (maxY - minY + 1 >= kCornerTestRows) {
        coveredWhole = true;
        for (const EdgeFunction& edge : t.edges) {
            const std::int64_t corners[4] = {edge.at(minX, minY), edge.at(maxX, minY), edge.at(minX, maxY),
                                             edge.at(maxX, maxY)};
            if (corners[0] < 0 && corners[1] < 0 && corners[2] < 0 && corners[3] < 0) return;
            if ((corners[0] | corners[1] | corners[2] | corners[3]) < 0) coveredWhole = false;
        }
    }
    for (int row = minY; row <= maxY; ++row) {
        const Span span = coveredWhole ? Span{minX, maxX} : coveredSpan(t, row, minX, maxX);
        if (span.begin <= span.end) kernels.span(t, row, span.begin, span.end, fb, counts);
    }
}

ExactKernels bestExactKernels() {
    // MYGL_KERNELS=avx2 or scalar caps the choice, to see how a CPU without AVX-512 (or AVX2)
    // would run: the pixels are the same.
    const char* cap = std::getenv("MYGL_KERNELS");
    const std::string_view limit = cap ? cap : "";
    if (cpuHasAvx512() && limit != "avx2" && limit != "scalar") return {shadeSpanAvx512, shadeNarrowTriangleAvx512};
    if (cpuHasAvx2Fma() && limit != "scalar") return {shadeSpanAvx2, nullptr};
    return {};
}

}  // namespace glrenderer
