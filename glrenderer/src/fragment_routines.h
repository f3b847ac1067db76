#pragma once
// The fragment routines of one vector width: the stage (fragment_stage.h) driven over the pixel
// sets coverage makes (spans of a row, 2D blocks of a narrow triangle), compiled once per fast
// key and once for any key. Included only by fragment_paths_*.cpp, each with its lane type.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <utility>

#include "fragment_paths.h"
#include "fragment_stage.h"
#include "packed_triangles.h"
#include "raster_span.h"
#include "raster_triangle.h"
#include "tile_columns.h"

namespace glrenderer {

template <class L>
[[gnu::always_inline]] inline void shadeSpan(const FragmentKey& key, const FragmentLanes<L>& lanes, int row, int begin,
                                             int end, Framebuffer& fb, FragmentCounts& counts) {
    const std::ptrdiff_t rowStart = static_cast<std::ptrdiff_t>(fb.height() - 1 - row) * fb.width();
    const PixelBuffers buffers{fb.color().data(), fb.depth().data(), fb.stencil().data()};
    const typename L::Float y = L::floats(static_cast<float>(row));
    std::uint64_t passed = 0;
    // With cheap masks, blocks are aligned to cache lines (the buffers are): a block across two
    // lines made every masked load and store touch both, a third of a dense frame. The first
    // block starts at the line holding `begin`, its lanes before it masked off.
    int first = begin;
    if constexpr (L::kCheapMasks && L::kCount > 1) {
        first -= static_cast<int>((rowStart + begin) % L::kCount);
    }
    // A level of detail per 2 x 2 quad: lanes in pairs from an even x (RowBlock::kQuadLanes).
    if (L::kCount > 1 && key.samplesLod()) first &= ~1;
    for (int px = first; px <= end; px += L::kCount) {
        const typename L::Mask covered = L::lanesBetween(begin - px, end - px);
        const typename L::Float x = L::toFloat(L::add(L::ints(px), L::laneIndex()));
        const bool whole = (px >= begin && px + L::kCount - 1 <= end) || blockInOneTile(px, L::kCount, fb.width());
        const RowBlock<L> block(rowStart + px, whole);
        passed += L::count(shadeBlock<L>(key, lanes, x, y, covered, block, buffers));
    }
    counts.fragments += static_cast<std::uint64_t>(end - begin + 1);
    counts.passed += passed;
}

// Lanes on a block of a narrow area: lane i is pixel (dx, dy) = (i % columns, i / columns) from
// the block's first pixel, columns a power of two; rows go down in memory as y goes up.
template <class L>
class NarrowBlock {
public:
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    static constexpr QuadLanes kQuadLanes = QuadLanes::PerLane;  // a level of detail per lane

    // `laneOffsets` holds each lane's dx - dy * (framebuffer width).
    NarrowBlock(std::size_t firstPixel, int rows, unsigned columns, std::size_t width, Int laneOffsets)
        : firstPixel_(firstPixel),
          rows_(rows),
          columns_(columns),
          width_(width),
          laneOffsets_(laneOffsets),
          firstRow_(L::lanesBetween(0, static_cast<int>(columns) - 1)) {}

    // A block of one or two rows: a masked load per row. More: one gather, which measured faster
    // than a masked load per row, which stalls behind the previous triangle's stores.
    Int load(const std::uint32_t* buffer, Mask lanes) const {
        if (rows_ > 2) return L::gather(buffer + firstPixel_, laneOffsets_, lanes);
        const Int first = L::load(buffer + firstPixel_, L::both(lanes, rowLanes(0)));
        if (rows_ == 1) return first;
        return L::bitOr(first, L::load(laneZero(buffer, 1), L::both(lanes, rowLanes(1))));
    }
    // A masked store per row (a scatter measured slower).
    void store(std::uint32_t* buffer, Mask lanes, Int values) const {
        for (int row = 0; row < rows_; ++row) {
            const Mask inRow = L::both(lanes, rowLanes(row));
            if (!L::none(inRow)) L::store(laneZero(buffer, row), inRow, values);
        }
    }

private:
    Mask rowLanes(int row) const { return L::moveLanesUp(firstRow_, row * static_cast<int>(columns_)); }

    // Where lane 0 would be for the lanes of `row` to land on their pixels of `buffer`. Formed
    // as an integer: it may lie before the buffer, where only masked-off lanes point.
    template <class T>
    T* laneZero(T* buffer, int row) const {
        T* rowStart = buffer + firstPixel_ - static_cast<std::size_t>(row) * width_;
        return reinterpret_cast<T*>(reinterpret_cast<std::uintptr_t>(rowStart) -
                                    sizeof(T) * static_cast<unsigned>(row) * columns_);
    }

    std::size_t firstPixel_;
    int rows_;
    unsigned columns_;
    std::size_t width_;
    Int laneOffsets_;
    Mask firstRow_;  // the lanes of the block's first row
};

// Lanes on two rows of a span walk (shadeRowPairs): the first half of the lanes on a row from
// `first`, the second half on the row after it, which lies a framebuffer width lower in memory.
template <class L>
class TwoRowBlock {
public:
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    static constexpr QuadLanes kQuadLanes = QuadLanes::TwoRows;

    // `whole`: bit 0 (first row) or 1 (second row) set where the row's lanes all lie in its
    // span, for plain loads and stores (L::loadHalves). A row of the pair outside the area has
    // no lanes, and is never touched: its place is formed as an integer, as it may lie before
    // the buffer.
    TwoRowBlock(std::size_t first, std::size_t width, unsigned whole) : first_(first), width_(width), whole_(whole) {}

    Int load(const std::uint32_t* buffer, Mask lanes) const {
        return L::loadHalves(buffer + first_, second(buffer), lanes, whole_);
    }
    void store(std::uint32_t* buffer, Mask lanes, Int values) const {
        L::storeHalves(buffer + first_, second(buffer), lanes, values, whole_);
    }

private:
    template <class T>
    T* second(T* buffer) const {
        return reinterpret_cast<T*>(reinterpret_cast<std::uintptr_t>(buffer + first_) - sizeof(T) * width_);
    }

    std::size_t first_, width_;
    unsigned whole_;
};

// Under a key that samples a level of detail: the rows of a triangle's part in `area` in pairs
// from an even row, in blocks of two rows of L::kCount / 2 lanes from an even x, so that a block
// holds its 2 x 2 quads whole and takes their level of detail from its own lanes
// (QuadLanes::TwoRows), where a block of one row evaluates the quads' other row.
template <class L>
[[gnu::always_inline]] inline void shadeRowPairs(const FragmentKey& key, const FragmentLanes<L>& lanes,
                                                 const RasterTriangle& t, const PixelRect& area, bool coveredWhole,
                                                 Framebuffer& fb, FragmentCounts& counts) {
    using Int = typename L::Int;
    using Mask = typename L::Mask;
    constexpr int kColumns = L::kCount / 2;
    const Int dx = L::bitAnd(L::laneIndex(), L::ints(kColumns - 1));
    const Int dy = L::template shiftRightUnsigned<std::countr_zero(static_cast<unsigned>(kColumns))>(L::laneIndex());
    const std::size_t fbWidth = static_cast<std::size_t>(fb.width());
    const Mask rowLanes[2] = {L::lanesBetween(0, kColumns - 1), L::lanesBetween(kColumns, L::kCount - 1)};
    const Mask allLanes = L::lanesBetween(0, L::kCount - 1);
    const PixelBuffers buffers{fb.color().data(), fb.depth().data(), fb.stencil().data()};
    AreaRows rows(t, area, coveredWhole);  // called for each row of the area in order
    const auto spanOf = [&](int row) { return row < area.minY || row > area.maxY ? Span{1, 0} : rows.next(); };
    std::uint64_t fragments = 0, passed = 0;
    for (int top = area.minY & ~1; top <= area.maxY; top += 2) {
        const Span first = spanOf(top), second = spanOf(top + 1);
        const int firstCount = std::max(first.end - first.begin + 1, 0);
        const int secondCount = std::max(second.end - second.begin + 1, 0);
        if (firstCount + secondCount == 0) continue;
        fragments += static_cast<std::uint64_t>(firstCount + secondCount);
        const int begin = (firstCount == 0    ? second.begin
                           : secondCount == 0 ? first.begin
                                              : std::min(first.begin, second.begin)) &
                          ~1;
        const int end = firstCount == 0 ? second.end : secondCount == 0 ? first.end : std::max(first.end, second.end);
        const std::size_t rowStart = static_cast<std::size_t>(fb.height() - 1 - top) * fbWidth;
        const typename L::Float y = L::toFloat(L::add(L::ints(top), dy));
        // Lane i is covered at the block from x = px where laneBegin_i <= px <= laneEnd_i.
        const Int laneBegin = L::sub(L::select(rowLanes[0], L::ints(first.begin), L::ints(second.begin)), dx);
        const Int laneEnd = L::sub(L::select(rowLanes[0], L::ints(first.end), L::ints(second.end)), dx);
        for (int px = begin; px <= end; px += kColumns) {
            const Int at = L::ints(px);
            const Mask covered = L::butNot(L::butNot(allLanes, L::lessThan(at, laneBegin)), L::lessThan(laneEnd, at));
            const typename L::Float x = L::toFloat(L::add(at, dx));
            const unsigned whole = (px >= first.begin && px + kColumns - 1 <= first.end ? 1u : 0u) |
                                   (px >= second.begin && px + kColumns - 1 <= second.end ? 2u : 0u);
            const TwoRowBlock<L> block(rowStart + static_cast<std::size_t>(px), fbWidth, whole);
            passed += L::count(shadeBlock<L>(key, lanes, x, y, covered, block, buffers));
        }
    }
    counts.fragments += fragments;
    counts.passed += passed;
}

// Under a key that samples a level of detail, a small triangle's part in `area` (up to two
// blocks across from its even x, fewer than 8 rows) in shadeRowPairs' 4 x 2 blocks from an even
// x and an even row, each lane's coverage from the edge functions instead of a span search per
// row. Returns false, drawing nothing, for a larger area (a tall one's row pairs have whole
// half-rows: measured faster there) or edge values beyond 32 bits.
template <class L>
[[gnu::always_inline]] inline bool shadeNarrowQuads(const FragmentKey& key, const FragmentLanes<L>& lanes,
                                                    const RasterTriangle& t, const PixelRect& area, Framebuffer& fb,
                                                    FragmentCounts& counts) {
    using Int = typename L::Int;
    using Mask = typename L::Mask;
    constexpr int kColumns = L::kCount / 2;
    const int left = area.minX & ~1;
    if (area.maxX - left >= 2 * kColumns || area.maxY - area.minY >= 7) return false;
    // A lane's edge value is formed in 32-bit wrapping arithmetic from a block's first value and
    // its steps, all taken modulo 2^32: exact where the true value fits in 32 bits, as it does
    // at every pixel of the area when it does at the area's corners (a linear function's
    // extremes). Lanes outside the area are masked off whatever their value.
    for (const EdgeFunction& edge : t.edges) {
        for (const int x : {area.minX, area.maxX}) {
            for (const int y : {area.minY, area.maxY}) {
                const std::int64_t value = edge.at(x, y);
                if (value < INT32_MIN || value > INT32_MAX) return false;
            }
        }
    }
    const Int dx = L::bitAnd(L::laneIndex(), L::ints(kColumns - 1));
    const Int dy = L::template shiftRightUnsigned<std::countr_zero(static_cast<unsigned>(kColumns))>(L::laneIndex());
    Int steps[3];  // each lane's edge value less its block's first lane's
    for (int k = 0; k < 3; ++k) {
        steps[k] = L::add(L::mul(dx, L::ints(static_cast<int>(t.edges[k].stepX))),
                          L::mul(dy, L::ints(static_cast<int>(t.edges[k].stepY))));
    }
    // Lane i lies in the area's columns at the block from x = px where columnBegin_i <= px <= columnEnd_i.
    const Int columnBegin = L::sub(L::ints(area.minX), dx), columnEnd = L::sub(L::ints(area.maxX), dx);
    const std::size_t fbWidth = static_cast<std::size_t>(fb.width());
    const PixelBuffers buffers{fb.color().data(), fb.depth().data(), fb.stencil().data()};
    std::uint64_t fragments = 0, passed = 0;
    for (int top = area.minY & ~1; top <= area.maxY; top += 2) {
        const Mask inRows = L::lanesBetween((area.minY - top) * kColumns, (area.maxY - top + 1) * kColumns - 1);
        const std::size_t rowStart = static_cast<std::size_t>(fb.height() - 1 - top) * fbWidth;
        const typename L::Float y = L::toFloat(L::add(L::ints(top), dy));
        for (int px = left; px <= area.maxX; px += kColumns) {
            const Int at = L::ints(px);
            Int outside = L::ints(0);  // sign bit set where any edge is negative
            for (int k = 0; k < 3; ++k) {
                outside = L::bitOr(outside, L::add(L::ints(static_cast<int>(t.edges[k].at(px, top))), steps[k]));
            }
            const Mask inArea = L::butNot(L::butNot(inRows, L::lessThan(at, columnBegin)), L::lessThan(columnEnd, at));
            const Mask covered = L::both(inArea, L::notNegative(outside));
            if (L::none(covered)) continue;
            fragments += L::count(covered);
            const TwoRowBlock<L> block(rowStart + static_cast<std::size_t>(px), fbWidth, 0);
            passed += L::count(shadeBlock<L>(key, lanes, L::toFloat(L::add(at, dx)), y, covered, block, buffers));
        }
    }
    counts.fragments += fragments;
    counts.passed += passed;
    return true;
}

// The rows of an area, their spans from `rows` (NarrowRows, AreaRows).
template <class L, class Rows>
[[gnu::always_inline]] inline void shadeWalkedRows(const FragmentKey& key, const FragmentLanes<L>& lanes, Rows rows,
                                                   const PixelRect& area, Framebuffer& fb, FragmentCounts& counts) {
    for (int row = area.minY; row <= area.maxY; ++row) {
        const Span span = rows.next();
        if (span.begin <= span.end) shadeSpan<L>(key, lanes, row, span.begin, span.end, fb, counts);
    }
}

// A part of an area at most L::kCount columns wide, one row at a time in one block of lanes
// from column `left` over all its columns, each lane's coverage taken from the edge functions in
// 32-bit lanes: no span to find and turn back into lanes (NarrowRows' walk and the span's set-up
// were a third of the rows routine's instructions in the torus). The block's planes' terms in x
// are formed once (FragmentLanes' ColumnsFixed). For edge values that fit 32 bits over the area
// (shadeNarrowQuads' wrapping arithmetic: narrowRowsFit).
template <class L>
[[gnu::always_inline]] inline void shadeNarrowRows(const FragmentKey& key, const RasterTriangle& t,
                                                   const PixelRect& part, int left, Framebuffer& fb,
                                                   std::uint64_t& fragments, std::uint64_t& passed) {
    using Int = typename L::Int;
    using Mask = typename L::Mask;
    const Mask inPart = L::lanesBetween(part.minX - left, part.maxX - left);
    const typename L::Float x = L::toFloat(L::add(L::ints(left), L::laneIndex()));
    FragmentLanes<L, true> lanes(key, t.fragment, fb.height());
    lanes.fixColumns(x);
    Int edges[3], down[3];
    for (int k = 0; k < 3; ++k) {
        const EdgeFunction& edge = t.edges[k];
        edges[k] = L::add(L::ints(static_cast<int>(edge.at(left, part.minY))),
                          L::mul(L::laneIndex(), L::ints(static_cast<int>(edge.stepX))));
        down[k] = L::ints(static_cast<int>(edge.stepY));
    }
    const bool whole = blockInOneTile(left, L::kCount, fb.width());
    const std::ptrdiff_t fbWidth = fb.width();
    const PixelBuffers buffers{fb.color().data(), fb.depth().data(), fb.stencil().data()};
    for (int row = part.minY; row <= part.maxY; ++row) {
        const Int outside = L::bitOr(L::bitOr(edges[0], edges[1]), edges[2]);  // sign bit: outside an edge
        for (int k = 0; k < 3; ++k) edges[k] = L::add(edges[k], down[k]);
        const Mask covered = L::both(inPart, L::notNegative(outside));
        if (L::none(covered)) continue;
        fragments += L::count(covered);
        const RowBlock<L> block((fb.height() - 1 - row) * fbWidth + left, whole);
        passed += L::count(shadeBlock<L>(key, lanes, x, L::floats(static_cast<float>(row)), covered, block, buffers));
    }
}

// Whether shadeNarrowParts may draw a triangle's part in `area`.
[[gnu::always_inline]] inline bool narrowRowsFit(const RasterTriangle& t, const PixelRect& area) {
    return smallEdgeSteps(t) || edgeValuesFit32(t, area);
}

// An area up to two blocks of lanes wide, a part of up to L::kCount columns at a time in
// shadeNarrowRows' blocks: on the L::kCount-aligned groups of columns that hold the area where
// as few do (in one tile: plain loads and stores, blockInOneTile, a cache line a row), else from
// the area's first column. (A lit torus's triangles up to 13 pixels across took a span search a
// row, over 2,000 instructions a triangle.)
template <class L>
[[gnu::always_inline]] inline void shadeNarrowParts(const FragmentKey& key, const RasterTriangle& t,
                                                    const PixelRect& area, Framebuffer& fb, FragmentCounts& counts) {
    const int aligned = area.minX & ~(L::kCount - 1);
    std::uint64_t fragments = 0, passed = 0;
    if (area.maxX - area.minX < L::kCount) {
        // One part, apart from the loop: a loop of one cost the torus's calls 27 instructions each.
        shadeNarrowRows<L>(key, t, area, area.maxX - aligned < L::kCount ? aligned : area.minX, fb, fragments, passed);
    } else {
        int left = area.maxX - aligned < 2 * L::kCount ? aligned : area.minX;
#pragma GCC unroll 1
        for (int part = 0; part < 2; ++part, left += L::kCount) {
            const PixelRect columns{std::max(left, area.minX), std::min(left + L::kCount - 1, area.maxX), area.minY,
                                    area.maxY};
            shadeNarrowRows<L>(key, t, columns, left, fb, fragments, passed);
        }
    }
    counts.fragments += fragments;
    counts.passed += passed;
}

// The rows of a triangle's part in `area` (FragmentRoutine::Rows).
template <class L>
[[gnu::always_inline]] inline void shadeRows(const FragmentKey& key, const RasterTriangle& t, const PixelRect& area,
                                             bool coveredWhole, Framebuffer& fb, FragmentCounts& counts) {
    if constexpr (L::kTwoRowBlocks) {
        if (key.samplesLod()) {
            const FragmentLanes<L> lanes(key, t.fragment, fb.height());
            if (!coveredWhole && shadeNarrowQuads<L>(key, lanes, t, area, fb, counts)) return;
            return shadeRowPairs<L>(key, lanes, t, area, coveredWhole, fb, counts);
        }
    }
    // At AVX2's width, areas up to two blocks wide one block a row per part (shadeNarrowParts);
    // areas under 8 columns wide at the scalar width, or with edge values beyond 32 bits,
    // NarrowRows' spans.
    const bool narrow = !coveredWhole && area.maxX - area.minX < NarrowRows<8>::kMaxColumns;
    if constexpr (!L::kNarrowBlocks && L::kCount == NarrowRows<8>::kMaxColumns) {
        if (!coveredWhole && area.maxX - area.minX < 2 * L::kCount && narrowRowsFit(t, area)) {
            return shadeNarrowParts<L>(key, t, area, fb, counts);
        }
    }
    const FragmentLanes<L> lanes(key, t.fragment, fb.height());
    // (Widths with narrow blocks draw such areas in them: measured slower with this walk too.)
    if constexpr (!L::kNarrowBlocks) {
        if (narrow) {
            if (area.maxX - area.minX < NarrowRows<4>::kMaxColumns)
                return shadeWalkedRows<L>(key, lanes, NarrowRows<4>(t, area.minX, area.maxX, area.minY), area, fb,
                                          counts);
            return shadeWalkedRows<L>(key, lanes, NarrowRows<8>(t, area.minX, area.maxX, area.minY), area, fb, counts);
        }
    }
    shadeWalkedRows<L>(key, lanes, AreaRows(t, area, coveredWhole), area, fb, counts);
}

// Areas up to L::kCount pixels wide, in blocks of L::kCount lanes (kCount x 1 up to 1 x kCount
// pixels, as narrow as the area), with no span search: most of a dense mesh's triangles are a
// few pixels across.
// (`key` by reference: for a fast path, the template's constant object, whose fields the compiler
// folds however long the routine; a copy's it folded only while the routine stayed small.)
template <class L>
[[gnu::always_inline]] inline bool shadeNarrowTriangle(const FragmentKey& key, const RasterTriangle& t,
                                                       const PixelRect& area, Framebuffer& fb, FragmentCounts& counts) {
    using Int = typename L::Int;
    using Mask = typename L::Mask;
    const int width = area.maxX - area.minX + 1;
    if (width > L::kCount) return false;
    const unsigned columns = std::bit_ceil(static_cast<unsigned>(width));
    const int columnBits = std::countr_zero(columns);
    const int blockRows = L::kCount >> columnBits;
    if (!smallEdgeSteps(t) && !edgeValuesFit32(t, area)) return false;
    const Int dx = L::bitAnd(L::laneIndex(), L::ints(static_cast<int>(columns - 1)));
    const Int dy = L::shiftRight(L::laneIndex(), columnBits);
    const typename L::Float x = L::toFloat(L::add(L::ints(area.minX), dx));
    const Mask inColumns = L::lessThan(dx, L::ints(width));
    const Int laneOffsets = L::sub(dx, L::mul(dy, L::ints(fb.width())));
    Int stepX[3], stepY[3];
    for (int k = 0; k < 3; ++k) {
        stepX[k] = L::mul(dx, L::ints(static_cast<int>(t.edges[k].stepX)));
        stepY[k] = L::mul(dy, L::ints(static_cast<int>(t.edges[k].stepY)));
    }
    const std::size_t fbWidth = static_cast<std::size_t>(fb.width());
    const PixelBuffers buffers{fb.color().data(), fb.depth().data(), fb.stencil().data()};
    const FragmentLanes<L> lanes(key, t.fragment, fb.height());
    std::uint64_t fragments = 0, passed = 0;
    for (int top = area.minY; top <= area.maxY; top += blockRows) {
        const int rows = std::min(blockRows, area.maxY - top + 1);
        Int outside = L::ints(0);  // sign bit set where any edge is negative
        for (int k = 0; k < 3; ++k) {
            const Int first = L::ints(static_cast<int>(t.edges[k].at(area.minX, top)));
            outside = L::bitOr(outside, L::add(first, L::add(stepX[k], stepY[k])));
        }
        const Mask inBlock = L::both(inColumns, L::lessThan(dy, L::ints(rows)));
        const Mask covered = L::both(inBlock, L::notNegative(outside));
        if (L::none(covered)) continue;
        fragments += L::count(covered);
        const std::size_t firstPixel =
            static_cast<std::size_t>(fb.height() - 1 - top) * fbWidth + static_cast<std::size_t>(area.minX);
        const NarrowBlock<L> block(firstPixel, rows, columns, fbWidth, laneOffsets);
        const typename L::Float y = L::toFloat(L::add(L::ints(top), dy));
        passed += L::count(shadeBlock<L>(key, lanes, x, y, covered, block, buffers));
    }
    counts.fragments += fragments;
    counts.passed += passed;
    return true;
}

// Whether a key's fast path packs tiny triangles (shadePackedRun): not with texels as depths or
// stencil values (glDrawPixels' rectangles), nor in deferred shading's passes (drawDeferred).
constexpr bool packsTinyTriangles(const FragmentKey& key) {
    return key.texelUse == TexelUse::Color && key.deferredPass == DeferredPass::None;
}

// Which keys of kFastFragmentKeys a width compiles fast paths for: all, or only those with (or
// without) a level of detail where other paths serve the rest (FragmentPaths' lodPaths).
enum class FastKeys { All, WithLod, WithoutLod };

constexpr bool compilesFastPath(FastKeys keys, const FragmentKey& key) {
    return keys == FastKeys::All || (keys == FastKeys::WithLod) == key.samplesLod();
}

// The indices in kFastFragmentKeys of the keys of `Keys`.
template <FastKeys Keys>
constexpr auto fastKeyIndices() {
    constexpr auto count = static_cast<std::size_t>(
        std::ranges::count_if(kFastFragmentKeys, [](const FragmentKey& key) { return compilesFastPath(Keys, key); }));
    std::array<std::size_t, count> indices{};
    std::size_t next = 0;
    for (std::size_t i = 0; i < std::size(kFastFragmentKeys); ++i) {
        if (compilesFastPath(Keys, kFastFragmentKeys[i])) indices[next++] = i;
    }
    return indices;
}

// A key with an address, for its fast paths' FragmentRoutine::key.
template <FragmentKey Key>
inline constexpr FragmentKey kKeyObject = Key;

// The routines of lane type L: per key of kFastFragmentKeys, the key a constant (a fast path),
// and for any key, read from the primitive at run time.
template <class L>
struct RoutinesOf {
    template <FragmentKey Key>
    static void span(const FragmentInputs& in, int row, int begin, int end, Framebuffer& fb, FragmentCounts& counts) {
        shadeSpan<L>(Key, FragmentLanes<L>(Key, in, fb.height()), row, begin, end, fb, counts);
    }
    static void anyKeySpan(const FragmentInputs& in, int row, int begin, int end, Framebuffer& fb,
                           FragmentCounts& counts) {
        shadeSpan<L>(in.key(), FragmentLanes<L>(in.key(), in, fb.height()), row, begin, end, fb, counts);
    }
    template <FragmentKey Key>
    static void rows(const RasterTriangle& t, const PixelRect& area, bool coveredWhole, Framebuffer& fb,
                     FragmentCounts& counts) {
        shadeRows<L>(Key, t, area, coveredWhole, fb, counts);
    }
    static void anyKeyRows(const RasterTriangle& t, const PixelRect& area, bool coveredWhole, Framebuffer& fb,
                           FragmentCounts& counts) {
        shadeRows<L>(t.fragment.key(), t, area, coveredWhole, fb, counts);
    }
    template <FragmentKey Key>
    static bool narrow(const RasterTriangle& t, const PixelRect& area, Framebuffer& fb, FragmentCounts& counts) {
        return shadeNarrowTriangle<L>(Key, t, area, fb, counts);
    }
    template <FragmentKey Key>
    static std::size_t packed(std::span<const RasterTriangle* const> run, const PixelRect& area, Framebuffer& fb,
                              FragmentCounts& counts) {
        return shadePackedRun<L>(Key, run, area, fb, counts);
    }
    static bool anyKeyNarrow(const RasterTriangle& t, const PixelRect& area, Framebuffer& fb, FragmentCounts& counts) {
        return shadeNarrowTriangle<L>(t.fragment.key(), t, area, fb, counts);
    }

    // The fast path of `Key`, with its deferred shading's if the key defers its colour.
    template <FragmentKey Key>
    static constexpr FragmentRoutine fastRoutine() {
        FragmentRoutine routine{&span<Key>, &rows<Key>, nullptr};
        routine.key = &kKeyObject<Key>;
        if constexpr (L::kNarrowBlocks) routine.narrow = &narrow<Key>;
        if constexpr (L::kPackedBlocks && packsTinyTriangles(Key)) routine.packed = &packed<Key>;
        if constexpr (Key.defersColor()) {
            routine.visibility = &DeferredPassesOf<Key>::visibility;
            routine.shade = &DeferredPassesOf<Key>::shade;
        }
        return routine;
    }
    template <FragmentKey Key>
    struct DeferredPassesOf {
        static constexpr FragmentRoutine visibility = fastRoutine<visibilityKey(Key)>();
        static constexpr FragmentRoutine shade = fastRoutine<shadeKey(Key)>();
    };
    template <FastKeys Keys, std::size_t... I>
    static constexpr auto fastPaths(std::index_sequence<I...>) {
        constexpr auto indices = fastKeyIndices<Keys>();
        return std::array<FragmentPaths::FastPath, sizeof...(I)>{
            {{kFastFragmentKeys[indices[I]], fastRoutine<kFastFragmentKeys[indices[I]]>()}...}};
    }
    static constexpr FragmentRoutine anyKey() {
        if constexpr (L::kNarrowBlocks)
            return {&anyKeySpan, &anyKeyRows, &anyKeyNarrow};
        else
            return {&anyKeySpan, &anyKeyRows, nullptr};
    }
};

// The paths of lane type L, in constants: nothing runs at static initialization, where the CPU
// may not have L's instructions. `LodPaths`: FragmentPaths' lodPaths; `Keys`: the fast keys compiled.
template <class L, FragmentPaths::PathsOf LodPaths = nullptr, FastKeys Keys = FastKeys::All>
const FragmentPaths& fragmentPathsOf() {
    static constexpr auto fast =
        RoutinesOf<L>::template fastPaths<Keys>(std::make_index_sequence<fastKeyIndices<Keys>().size()>());
    static constexpr FragmentPaths paths(L::kName, fast, RoutinesOf<L>::anyKey(), LodPaths);
    return paths;
}

}  // namespace glrenderer
