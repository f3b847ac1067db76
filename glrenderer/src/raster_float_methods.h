#pragma once
#include "raster_span.h"

namespace glrenderer {

// The seed documents' float rasterizers, on unsnapped window coordinates. Shading, depth and
// counting are the exact method's (the triangle's fragment path); only coverage differs.

// Seed 001: per scanline, x where the float edges cross the row's center line, pixels from
// ceil(x_left - 0.5) to ceil(x_right - 0.5) - 1, rows likewise: Direct3D's top-left rule in the
// y-down window, i.e. the GL reference's rule mirrored for horizontal edges.
void rasterizeScanline(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                       FragmentCounts& counts);

// Seed 004: float edge functions evaluated at every pixel center of the bounding box, a pixel
// inside when no edge function is negative: shared edges are drawn by both triangles.
void rasterizeBoundingBoxFloat(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                               FragmentCounts& counts);

// Draws `triangle` with a method other than the exact one (RasterMethod::Exact).
void rasterizeWithSlowerMethod(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                               FragmentCounts& counts);

// Draws `triangle` with the method it was prepared for: the exact one inline.
inline void rasterizeWithMethod(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                                FragmentCounts& counts) {
    if (triangle.method == RasterMethod::Exact) [[likely]]
        return rasterizeTriangleSpans(triangle, rect, framebuffer, counts, *triangle.fragment.routine);
    rasterizeWithSlowerMethod(triangle, rect, framebuffer, counts);
}

}  // namespace glrenderer
