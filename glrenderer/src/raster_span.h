#pragma once
#include <bit>
#include <cstdint>

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

// The covered span of each row of an area up to kMaxColumns wide, row after row: the edge
// functions at the area's first column stepped down a row at a time, and every column tested
// without a branch (a row of a dense mesh's triangle cost a call, three evaluations of the edge
// functions and a branch per pixel in coveredSpan).
class NarrowRows {
public:
    static constexpr int kMaxColumns = 4;

    // The area's columns [minX, maxX] (at most kMaxColumns), from `row` on.
    NarrowRows(const RasterTriangle& t, int minX, int maxX, int row)
        : minX_(minX), columnBits_((1u << (maxX - minX + 1)) - 1) {
        for (int k = 0; k < 3; ++k) {
            value_[k] = t.edges[k].at(minX, row);
            stepX_[k] = t.edges[k].stepX;
            stepY_[k] = t.edges[k].stepY;
        }
    }

    // The current row's span (coveredSpan's), then the next row.
    Span next() {
        unsigned covered = 0;  // bit c: column minX + c
        std::int64_t e0 = value_[0], e1 = value_[1], e2 = value_[2];
        for (int c = 0; c < kMaxColumns; ++c, e0 += stepX_[0], e1 += stepX_[1], e2 += stepX_[2]) {
            covered |= static_cast<unsigned>((e0 | e1 | e2) >= 0) << c;
        }
        for (int k = 0; k < 3; ++k) value_[k] += stepY_[k];
        covered &= columnBits_;
        // A row's covered pixels are contiguous.
        if (covered == 0) return {1, 0};
        return {minX_ + std::countr_zero(covered), minX_ + 31 - std::countl_zero(covered)};
    }

private:
    int minX_;
    unsigned columnBits_;
    std::int64_t value_[3], stepX_[3], stepY_[3];
};

// The fast exact method: spans from the edge functions, or the narrow blocks of `routine` where
// it has them, shaded by `routine` (the triangle's own, or another width's for the same key).
// Bit-for-bit the same pixels, depths and counts as rasterizeTriangleExact.
void rasterizeTriangleSpans(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                            FragmentCounts& counts, const FragmentRoutine& routine);

}  // namespace glrenderer
