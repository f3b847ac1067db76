#pragma once
#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "fragment_inputs.h"
#include "raster_triangle.h"

// The row walkers below are inlined into the fragment routines of every instruction set: each
// member is forced inline, as every function those routines share with the scalar code must be
// (tests/isa: an out-of-line copy compiled for AVX2 may be the one the linker keeps for all).

namespace glrenderer {

// The columns [begin, end] of one pixel row that a triangle covers, found exactly from its
// three integer edge functions: one division per edge, or for a few columns a test per pixel
// from each end.
struct Span {
    int begin, end;  // inclusive; empty when begin > end
};
Span coveredSpan(const RasterTriangle& triangle, int row, int minX, int maxX);

// coveredSpan's spans of consecutive rows of an area, row after row, for areas of many rows:
// each edge's bound on x is floor(value / |stepX|) at the row's start, kept as a quotient and a
// remainder and stepped exactly to the next row by stepY's own quotient and remainder, where
// coveredSpan divides three times a row (a tenth of bench-textured-cubes' frame).
class SteppedRows {
public:
    // Areas of fewer rows search each row (coveredSpan): stepping costs two divisions an edge
    // once, a row's search three divisions (or a test per pixel of a narrow row).
    static constexpr int kMinRows = 3;

    // The area's columns [minX, maxX], from `row` on.
    SteppedRows(const RasterTriangle& t, int minX, int maxX, int row);

    // The current row's span, then the next row.
    [[gnu::always_inline]] Span next() {
        std::int64_t begin = minX_, end = maxX_;
        bool outside = false;
        for (Bound& bound : bounds_) {
            // x >= -floor(value / stepX) for stepX > 0, x <= floor(value / -stepX) for stepX < 0,
            // and for stepX = 0 value >= 0 (the quotient is the value, divided by 1).
            if (bound.kind == Bound::Begin) begin = std::max(begin, -bound.quotient);
            if (bound.kind == Bound::End) end = std::min(end, bound.quotient);
            if (bound.kind == Bound::Row) outside |= bound.quotient < 0;
            // Without a branch: the carry is as likely as not, row after row.
            bound.remainder += bound.stepRemainder;
            const std::int64_t carry = bound.remainder >= bound.divisor ? 1 : 0;
            bound.quotient += bound.stepQuotient + carry;
            bound.remainder -= bound.divisor & -carry;
        }
        if (outside || begin > end) return {1, 0};
        return {static_cast<int>(begin), static_cast<int>(end)};
    }

private:
    // value = quotient * divisor + remainder, 0 <= remainder < divisor; stepY likewise.
    struct Bound {
        enum Kind { Begin, End, Row } kind;
        std::int64_t quotient, remainder, stepQuotient, stepRemainder, divisor;
    };
    std::int64_t minX_, maxX_;
    Bound bounds_[3];
};

// The covered span of each row of an area, row after row, the cheapest way: the whole row where
// the triangle covers the area whole, SteppedRows for SteppedRows::kMinRows rows or more, else a
// search per row (coveredSpan).
class AreaRows {
public:
    [[gnu::always_inline]] AreaRows(const RasterTriangle& t, const PixelRect& area, bool coveredWhole)
        : triangle_(t), area_(area), row_(area.minY), coveredWhole_(coveredWhole) {
        if (!coveredWhole && area.maxY - area.minY + 1 >= SteppedRows::kMinRows)
            stepped_.emplace(t, area.minX, area.maxX, area.minY);
    }

    // The current row's span, then the next row.
    [[gnu::always_inline]] Span next() {
        const int row = row_++;
        if (coveredWhole_) return {area_.minX, area_.maxX};
        if (stepped_) return stepped_->next();
        return coveredSpan(triangle_, row, area_.minX, area_.maxX);
    }

private:
    const RasterTriangle& triangle_;
    PixelRect area_;
    int row_;
    bool coveredWhole_;
    std::optional<SteppedRows> stepped_;
};

// The covered span of each row of an area up to `Columns` wide (4 or 8), row after row: the
// edge functions at the area's columns in 64-bit SSE lanes, stepped down a row at a time, and
// the columns' signs taken at once (a row of a dense mesh's triangle cost a call, three
// evaluations of the edge functions and a branch per pixel in coveredSpan, and a row of 5-8
// columns three 64-bit divisions there). Eight columns cost twice four's steps: an area four
// wide takes NarrowRows<4>.
template <int Columns>
class NarrowRows {
public:
    static_assert(Columns == 4 || Columns == 8);
    static constexpr int kMaxColumns = Columns;

    // The area's columns [minX, maxX] (at most kMaxColumns), from `row` on.
    [[gnu::always_inline]] NarrowRows(const RasterTriangle& t, int minX, int maxX, int row)
        : minX_(minX), columnBits_((1u << (maxX - minX + 1)) - 1) {
        for (int k = 0; k < 3; ++k) {
            const EdgeFunction& edge = t.edges[k];
            const std::int64_t value = edge.at(minX, row);
            for (int pair = 0; pair < kPairs; ++pair) {  // columns 2 * pair and 2 * pair + 1
                pairs_[k][pair] = _mm_set_epi64x(value + (2 * pair + 1) * edge.stepX, value + 2 * pair * edge.stepX);
            }
            down_[k] = _mm_set1_epi64x(edge.stepY);
        }
    }

    // The current row's span (coveredSpan's), then the next row.
    [[gnu::always_inline]] Span next() {
        // Bit c set where column minX + c is outside an edge (a negative value).
        unsigned outside = 0;
        for (int pair = 0; pair < kPairs; ++pair) {
            const __m128i either = _mm_or_si128(_mm_or_si128(pairs_[0][pair], pairs_[1][pair]), pairs_[2][pair]);
            outside |= static_cast<unsigned>(_mm_movemask_pd(_mm_castsi128_pd(either))) << (2 * pair);
            for (int k = 0; k < 3; ++k) pairs_[k][pair] = _mm_add_epi64(pairs_[k][pair], down_[k]);
        }
        const unsigned covered = ~outside & columnBits_;
        // A row's covered pixels are contiguous.
        if (covered == 0) return {1, 0};
        return {minX_ + std::countr_zero(covered), minX_ + 31 - std::countl_zero(covered)};
    }

private:
    static constexpr int kPairs = Columns / 2;
    int minX_;
    unsigned columnBits_;
    __m128i pairs_[3][kPairs], down_[3];
};

// Whether a triangle's edge values fit 32-bit lanes over `area` (the narrow blocks of
// fragment_routines.h): they hold every value of every block when the steps are below 2^25 and
// the values at the area's corners (the extremes of a linear function) below 2^29. Out of line:
// smallEdgeSteps decides for all but large triangles, and this code inlined in the narrow
// routines cost them their key's constants (the compiler stopped folding the key).
bool edgeValuesFit32(const RasterTriangle& triangle, const PixelRect& area);

// A sufficient test for edgeValuesFit32 on any area within the triangle's bounds, true for any
// triangle under 32 pixels across: the steps are the vertices' differences (dx, dy) times 256,
// so |dx|, |dy| <= 2^13 in 1/256 pixel; the area's corners are pixel centers P at most a pixel
// outside the vertices' span, so |E(P)| = |dx (P.x - a.x) + dy (P.y - a.y) + bias|
// <= 2 * 2^13 * (2^13 + 2^8) + 1 < 2^28. (An OR of the steps offset by the limit: below twice
// it, a power of two, iff each is.)
[[gnu::always_inline]] inline bool smallEdgeSteps(const RasterTriangle& t) {
    constexpr std::int64_t kLimit = std::int64_t{1} << 21;
    std::uint64_t offsetSteps = 0;
    for (const EdgeFunction& edge : t.edges) {
        offsetSteps |=
            static_cast<std::uint64_t>(edge.stepX + kLimit) | static_cast<std::uint64_t>(edge.stepY + kLimit);
    }
    return offsetSteps < static_cast<std::uint64_t>(2 * kLimit);
}

// From this many rows, an area's corners are tested first (rasterizeTallArea): not worth it for a few.
inline constexpr int kCornerTestRows = 8;

// rasterizeTriangleSpans for an area of many rows: the routine's rows after a test of the area's
// corners (none of it covered, or all of it).
void rasterizeTallArea(const RasterTriangle& triangle, const PixelRect& area, Framebuffer& framebuffer,
                       FragmentCounts& counts, const FragmentRoutine& routine);

// The fast exact method: spans from the edge functions, or the narrow blocks of `routine` where
// it has them, shaded by `routine` (the triangle's own, or another width's for the same key).
// Bit-for-bit the same pixels, depths and counts as rasterizeTriangleExact.
// Inline: every triangle of every tile passes here, and as a call of its own it took a tenth of
// a dense mesh's per-triangle instructions between the tile's loop and the routine.
[[gnu::always_inline]] inline void rasterizeTriangleSpans(const RasterTriangle& t, const PixelRect& rect,
                                                          Framebuffer& fb, FragmentCounts& counts,
                                                          const FragmentRoutine& routine) {
    // (`rect` is a tile's, inside the framebuffer: drawTile. No invariant check here: this is
    // inlined into the ISA files, which must share no function with the rest, IsaObjectsShareNoCode.)
    const PixelRect area{std::max(t.minX, rect.minX), std::min(t.maxX, rect.maxX), std::max(t.minY, rect.minY),
                         std::min(t.maxY, rect.maxY)};
    if (area.minX > area.maxX || area.minY > area.maxY) return;
    if (routine.narrow && routine.narrow(t, area, fb, counts)) return;
    if (area.maxY - area.minY + 1 >= kCornerTestRows) return rasterizeTallArea(t, area, fb, counts, routine);
    routine.rows(t, area, false, fb, counts);
}

// Consecutive triangles of routines that pack tiny triangles (FragmentRoutine::packed), in
// order, their parts in tile `rect`: each routine draws its own from the front.
inline void rasterizePackedRun(std::span<const RasterTriangle* const> run, const PixelRect& rect,
                               Framebuffer& framebuffer, FragmentCounts& counts) {
    for (std::size_t drawn = 0; drawn < run.size();) {
        const std::span<const RasterTriangle* const> rest = run.subspan(drawn);
        drawn += rest.front()->fragment.routine->packed(rest, rect, framebuffer, counts);
    }
}

}  // namespace glrenderer
