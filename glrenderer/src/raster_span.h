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
// 8 pixels at a time with AVX2 and FMA; only on CPUs that have both (cpuHasAvx2Fma()).
void shadeSpanAvx2(const RasterTriangle& triangle, int row, int begin, int end,
                   Framebuffer& framebuffer, FragmentCounts& counts);
// 16 pixels at a time with AVX-512F; only on CPUs that have it (cpuHasAvx512()).
void shadeSpanAvx512(const RasterTriangle& triangle, int row, int begin, int end,
                     Framebuffer& framebuffer, FragmentCounts& counts);

// Draws a narrow triangle's part in `area` (its bounds within a tile) in 2D blocks of pixels,
// with no span search, exactly as rasterizeTriangleExact would; returns false, drawing nothing,
// if the area is too wide for it.
using NarrowTriangleShader = bool (*)(const RasterTriangle& triangle, const PixelRect& area,
                                      Framebuffer& framebuffer, FragmentCounts& counts);
// Areas up to 16 pixels wide, in blocks of 16 AVX-512F lanes (16x1 up to 1x16 pixels, as
// narrow as the area); only on CPUs that have AVX-512F.
bool shadeNarrowTriangleAvx512(const RasterTriangle& triangle, const PixelRect& area, Framebuffer& framebuffer,
                               FragmentCounts& counts);

// The exact method's kernels for one CPU: spans, and optionally blocks for narrow triangles
// (most of a dense mesh's, which are a few pixels across).
struct ExactKernels {
    SpanShader span = shadeSpanScalar;
    NarrowTriangleShader narrow = nullptr;
};

// The fastest kernels this CPU runs.
ExactKernels bestExactKernels();

// The fast exact method: spans from the edge functions, shaded by `kernels`. Bit-for-bit the
// same pixels, depths and counts as rasterizeTriangleExact.
void rasterizeTriangleSpans(const RasterTriangle& triangle, const PixelRect& rect,
                            Framebuffer& framebuffer, FragmentCounts& counts, const ExactKernels& kernels);

}  // namespace glrenderer
