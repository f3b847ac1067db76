#pragma once
#include "raster_triangle.h"

namespace glrenderer {

// The columns [begin, end] of one pixel row that a triangle covers, found exactly from its
// three integer edge functions (one division per edge) instead of testing every pixel.
struct Span {
    int begin, end;  // inclusive; empty when begin > end
};
Span coveredSpan(const RasterTriangle& triangle, int row, int minX, int maxX);

// Shades the pixels [begin, end] of `row`, exactly as rasterizeTriangleExact shades each pixel.
using SpanShader = void (*)(const RasterTriangle& triangle, int row, int begin, int end,
                            Framebuffer& framebuffer, FragmentCounts& counts);
void shadeSpanScalar(const RasterTriangle& triangle, int row, int begin, int end,
                     Framebuffer& framebuffer, FragmentCounts& counts);
// 8 pixels at a time with AVX2 and FMA; only on CPUs that have both.
void shadeSpanAvx2(const RasterTriangle& triangle, int row, int begin, int end,
                   Framebuffer& framebuffer, FragmentCounts& counts);
bool cpuHasAvx2Fma();
// 16 pixels at a time with AVX-512F; only on CPUs that have it.
void shadeSpanAvx512(const RasterTriangle& triangle, int row, int begin, int end,
                     Framebuffer& framebuffer, FragmentCounts& counts);
bool cpuHasAvx512();

// The fastest span shader this CPU runs.
SpanShader bestSpanShader();

// The fast exact method: spans from the edge functions, shaded by `shader`. Bit-for-bit the
// same pixels, depths and counts as rasterizeTriangleExact.
void rasterizeTriangleSpans(const RasterTriangle& triangle, const PixelRect& rect,
                            Framebuffer& framebuffer, FragmentCounts& counts, SpanShader shader);

}  // namespace glrenderer
