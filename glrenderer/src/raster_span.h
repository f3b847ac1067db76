#pragma once
#include "fragment_inputs.h"
#include "raster_triangle.h"

namespace glrenderer {

// The columns [begin, end] of one pixel row that a triangle covers, found exactly from its
// three integer edge functions: one division per edge, or for a few columns a test per pixel
// from each end.
struct Span {
    int begin, end;  // inclusive; empty when begin > end
};
Span coveredSpan(const RasterTriangle& triangle, int row, int minX, int maxX);

// The fast exact method: spans from the edge functions, or the narrow blocks of `routine` where
// it has them, shaded by `routine` (the triangle's own, or another width's for the same key).
// Bit-for-bit the same pixels, depths and counts as rasterizeTriangleExact.
void rasterizeTriangleSpans(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                            FragmentCounts& counts, const FragmentRoutine& routine);

}  // namespace glrenderer
