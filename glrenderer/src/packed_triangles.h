#pragma once
// Several tiny triangles' fragments in one block of lanes: a dense mesh's triangles cover about
// two pixels each, and a block per triangle left most of its 16 lanes idle. Each lane carries its
// own triangle's planes (FragmentLanes::take), so every lane computes what it computes in a block
// of its own triangle, bit for bit. Included only by fragment_routines.h, at widths with
// L::kPackedBlocks.
// (A level of detail: every lane evaluates its own quad's corners from its own planes,
// QuadLanes::PerLane, as the reference's quads from even x and y do, covered or not.)
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "fragment_stage.h"
#include "raster_span.h"
#include "raster_triangle.h"
#include "triangle_arena.h"

namespace glrenderer {

// The lanes a tiny triangle's coverage is found in (TinyCoverage): L's own, or wider ones
// (fragment_paths_avx2_evex.cpp), compressed from there into L's.
template <class L>
struct CoverageLanesOf {
    using type = L;
};

// Lanes on any pixels: lane i at offsets[i] from a pixel of the buffers, read by a gather and
// written by a scatter. No two lanes on one pixel.
template <class L>
class PackedBlock {
public:
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    static constexpr QuadLanes kQuadLanes = QuadLanes::PerLane;

    PackedBlock(std::size_t origin, Int offsets) : origin_(origin), offsets_(offsets) {}

    Int load(const std::uint32_t* buffer, Mask lanes) const { return L::gather(buffer + origin_, offsets_, lanes); }
    void store(std::uint32_t* buffer, Mask lanes, Int values) const {
        L::scatter(buffer + origin_, offsets_, lanes, values);
    }

private:
    std::size_t origin_;
    Int offsets_;
};

// The pixel centres a triangle covers in a tile, when its part there fits two blocks of lanes in
// a narrow block's layout (shadeNarrowTriangle), one above the other: per block, `covered` the
// lanes, `at` each lane's pixel from the tile's first one, x in the low 16 bits and y in the high.
template <class L>
struct TinyCoverage {
    typename L::Int at[2];
    typename L::Mask covered[2];
    int counts[2];
    int blocks;
    int count;  // of both
};

// The coverage of triangle `t` in tile `rect` if its part there fits two blocks (an empty part
// does, covering nothing) and its edge values fit 32 bits there; false otherwise.
template <class L>
[[gnu::always_inline]] inline bool tinyCoverage(const RasterTriangle& t, const PixelRect& rect, TinyCoverage<L>& out) {
    using Int = typename L::Int;
    const PixelRect area{std::max(t.minX, rect.minX), std::min(t.maxX, rect.maxX), std::max(t.minY, rect.minY),
                         std::min(t.maxY, rect.maxY)};
    out.count = 0, out.blocks = 0;
    if (area.minX > area.maxX || area.minY > area.maxY) return true;
    const int width = area.maxX - area.minX + 1, height = area.maxY - area.minY + 1;
    if (width > L::kCount) return false;
    const unsigned columns = std::bit_ceil(static_cast<unsigned>(width));
    const int columnBits = std::countr_zero(columns);
    const int blockRows = L::kCount >> columnBits;
    if (height > 2 * blockRows) return false;
    if (!smallEdgeSteps(t) && !edgeValuesFit32(t, area)) return false;
    const Int dx = L::bitAnd(L::laneIndex(), L::ints(static_cast<int>(columns - 1)));
    const Int dy = L::shiftRight(L::laneIndex(), columnBits);
    Int steps[3];  // each lane's edge value less its block's first lane's
    for (int k = 0; k < 3; ++k) {
        steps[k] = L::add(L::mul(dx, L::ints(static_cast<int>(t.edges[k].stepX))),
                          L::mul(dy, L::ints(static_cast<int>(t.edges[k].stepY))));
    }
    const typename L::Mask inColumns = L::lessThan(dx, L::ints(width));
    const Int lanePixel = L::add(dx, L::template shiftLeft<16>(dy));
    out.blocks = height > blockRows ? 2 : 1;
    for (int block = 0; block < out.blocks; ++block) {
        const int top = area.minY + block * blockRows;
        Int outside = L::ints(0);  // sign bit set where any edge is negative
        for (int k = 0; k < 3; ++k) {
            outside = L::bitOr(outside, L::add(L::ints(static_cast<int>(t.edges[k].at(area.minX, top))), steps[k]));
        }
        const typename L::Mask inArea = L::both(inColumns, L::lessThan(dy, L::ints(area.maxY - top + 1)));
        out.covered[block] = L::both(inArea, L::notNegative(outside));
        out.counts[block] = static_cast<int>(L::count(out.covered[block]));
        out.count += out.counts[block];
        out.at[block] = L::add(L::ints((area.minX - rect.minX) | ((top - rect.minY) << 16)), lanePixel);
    }
    return true;
}

// `into` with the pixels `c` covers in its lanes from `used` on, in order.
template <class L, class C>
[[gnu::always_inline]] inline typename L::Int placeCoverage(typename L::Int into, int used, const TinyCoverage<C>& c) {
    for (int block = 0; block < c.blocks; ++block) {
        if (c.counts[block] == 0) continue;
        const typename L::Mask lanes = L::lanesBetween(used, used + c.counts[block] - 1);
        into = L::placeLanes(into, lanes, C::compress(c.at[block], c.covered[block]));
        used += c.counts[block];
    }
    return into;
}

// Consecutive triangles in tile `rect` up to one of another routine (FragmentRoutine::Packed):
// the covered pixels of consecutive tiny ones in the next free lanes of one block, until one
// does not fit, has other draw constants, or covers a pixel the block holds already (its
// fragment must follow the earlier one's: depth test, blending, counts); the others as by
// rasterizeTriangleSpans, in order. Returns how many it drew.
template <class L>
[[gnu::always_inline]] inline std::size_t shadePackedRun(const FragmentKey& key,
                                                         std::span<const RasterTriangle* const> run,
                                                         const PixelRect& rect, Framebuffer& fb,
                                                         FragmentCounts& counts) {
    using Int = typename L::Int;
    using Mask = typename L::Mask;
    using C = typename CoverageLanesOf<L>::type;
    const FragmentRoutine& routine = *run.front()->fragment.routine;
    const PixelBuffers buffers{fb.color().data(), fb.depth().data(), fb.stencil().data()};
    const std::size_t origin =
        static_cast<std::size_t>(fb.height() - 1 - rect.minY) * static_cast<std::size_t>(fb.width()) +
        static_cast<std::size_t>(rect.minX);
    const Int rowStep = L::ints(fb.width());
    std::uint64_t fragments = 0, passed = 0;
    TinyCoverage<C> c;
    // Whether `c` holds the coverage of run[i], found by the block before it: 1 (tiny), 0 (not)
    // or -1 (nothing).
    int carried = -1;
    const auto fetchAhead = [&](std::size_t i) {
        if (i + kPackedFetchAhead < run.size()) prefetchTriangle(*run[i + kPackedFetchAhead], triangleBytesRead(key));
    };
    std::size_t i = 0;
    while (i < run.size() && run[i]->fragment.routine == &routine) {
        fetchAhead(i);
        const RasterTriangle& first = *run[i++];
        const bool tiny = carried >= 0 ? carried == 1 : tinyCoverage<C>(first, rect, c);
        carried = -1;
        if (!tiny || c.count > L::kCount) {
            rasterizeTriangleSpans(first, rect, fb, counts, routine);
            continue;
        }
        if (c.count == 0) continue;
        FragmentLanes<L> lanes(key, first.fragment, fb.height());
        Int at = placeCoverage<L>(L::ints(0), 0, c);
        Mask group = L::lanesBetween(0, c.count - 1);
        int used = c.count;
        fragments += static_cast<std::uint64_t>(c.count);
        for (; i < run.size(); ++i) {
            fetchAhead(i);
            carried = -1;
            const RasterTriangle& t = *run[i];
            if (t.fragment.routine != &routine || !sameDrawConstants(key, first.fragment, t.fragment)) break;
            carried = tinyCoverage<C>(t, rect, c) ? 1 : 0;
            if (carried == 0 || used + c.count > L::kCount) break;
            if (c.count == 0) continue;
            const Mask added = L::lanesBetween(used, used + c.count - 1);
            const Int merged = placeCoverage<L>(at, used, c);
            if (L::repeatsAny(merged, group, added)) break;
            lanes.take(t.fragment, added);
            at = merged, group = L::either(group, added), used += c.count;
            fragments += static_cast<std::uint64_t>(c.count);
        }
        const Int dx = L::bitAnd(at, L::ints(0xFFFF)), dy = L::template shiftRightUnsigned<16>(at);
        const typename L::Float x = L::toFloat(L::add(dx, L::ints(rect.minX)));
        const typename L::Float y = L::toFloat(L::add(dy, L::ints(rect.minY)));
        const PackedBlock<L> block(origin, L::sub(dx, L::mul(dy, rowStep)));
        passed += L::count(shadeBlock<L>(key, lanes, x, y, group, block, buffers));
    }
    counts.fragments += fragments;
    counts.passed += passed;
    return i;
}

}  // namespace glrenderer
