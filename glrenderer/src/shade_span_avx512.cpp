// The shaders for CPUs with AVX-512F, 16 pixels per step: spans, and 2D blocks for narrow
// triangles. Compiled with -mavx512f -mfma and called only after cpuHasAvx512(). Each lane
// performs the scalar kernel's operations in the same order, so the bits match shadeSpanScalar
// (and the AVX2 shader) exactly; what changes is the width and the mask registers, which make
// the partial blocks as cheap as whole ones.
#include <immintrin.h>

#include <bit>
#include <cstdint>
#include <cstdlib>

#include "raster_span.h"

namespace glrenderer {
namespace {

struct PlaneLanes {
    __m512 a0, dadx, dady;
    explicit PlaneLanes(const AttributePlane& p)
        : a0(_mm512_set1_ps(p.a0)), dadx(_mm512_set1_ps(p.dadx)), dady(_mm512_set1_ps(p.dady)) {}
    __m512 at(__m512 x, __m512 y) const { return _mm512_fmadd_ps(dady, y, _mm512_fmadd_ps(dadx, x, a0)); }
};

__m512 clampUnit(__m512 v) {  // NaN and negatives to 0, like the scalar clamp
    return _mm512_min_ps(_mm512_max_ps(v, _mm512_setzero_ps()), _mm512_set1_ps(1.0f));
}

__m512i toDepth24(__m512 z) {
    return _mm512_cvtps_epi32(_mm512_mul_ps(clampUnit(z), _mm512_set1_ps(16777215.0f)));
}

__m512i fragmentToUnorm8(__m512 v) {
    const __m512 biased = _mm512_add_ps(_mm512_mul_ps(clampUnit(v), _mm512_set1_ps(255.0f / 256.0f)),
                                        _mm512_set1_ps(32768.0f));
    return _mm512_and_si512(_mm512_castps_si512(biased), _mm512_set1_epi32(0xFF));
}

// Lanes of `active` where incoming passes against stored (depths are below 2^24).
__mmask16 depthPassMask(CompareFunc func, __mmask16 active, __m512i incoming, __m512i stored) {
    switch (func) {
    case CompareFunc::Never: return 0;
    case CompareFunc::Less: return _mm512_mask_cmplt_epu32_mask(active, incoming, stored);
    case CompareFunc::Equal: return _mm512_mask_cmpeq_epu32_mask(active, incoming, stored);
    case CompareFunc::LessEqual: return _mm512_mask_cmple_epu32_mask(active, incoming, stored);
    case CompareFunc::Greater: return _mm512_mask_cmpgt_epu32_mask(active, incoming, stored);
    case CompareFunc::NotEqual: return _mm512_mask_cmpneq_epu32_mask(active, incoming, stored);
    case CompareFunc::GreaterEqual: return _mm512_mask_cmpge_epu32_mask(active, incoming, stored);
    case CompareFunc::Always: return active;
    }
    return 0;
}

// A triangle's planes and flat color broadcast to the 16 lanes, and what every shader computes
// from them for a block of pixels at (x, y).
class TriangleLanes {
public:
    explicit TriangleLanes(const RasterTriangle& t)
        : t_(t), depth_(t.depth), invW_(t.invW), r_(t.color[0]), g_(t.color[1]), b_(t.color[2]), a_(t.color[3]) {}

    __m512i depth24(__m512 x, __m512 y) const { return toDepth24(depth_.at(x, y)); }

    __m512i rgba(__m512 x, __m512 y) const {
        if (!t_.state.smooth) return _mm512_set1_epi32(static_cast<int>(t_.flatColor));
        __m512 red = r_.at(x, y), green = g_.at(x, y), blue = b_.at(x, y), alpha = a_.at(x, y);
        if (t_.state.perspective) {
            const __m512 w = _mm512_div_ps(_mm512_set1_ps(1.0f), invW_.at(x, y));
            red = _mm512_mul_ps(red, w), green = _mm512_mul_ps(green, w);
            blue = _mm512_mul_ps(blue, w), alpha = _mm512_mul_ps(alpha, w);
        }
        return _mm512_or_si512(
            _mm512_or_si512(fragmentToUnorm8(red), _mm512_slli_epi32(fragmentToUnorm8(green), 8)),
            _mm512_or_si512(_mm512_slli_epi32(fragmentToUnorm8(blue), 16),
                            _mm512_slli_epi32(fragmentToUnorm8(alpha), 24)));
    }

private:
    const RasterTriangle& t_;
    PlaneLanes depth_, invW_, r_, g_, b_, a_;
};

// A function, not a constant: a static initializer would run AVX-512 code on any CPU.
__m512i laneIndex() { return _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }

// Rows of a narrow area as blocks of lanes: lane i is pixel (dx, dy) = (i % columns,
// i / columns) of the block, columns a power of two.
class PixelBlock {
public:
    // `laneOffsets` holds each lane's dx - dy * (framebuffer width): rows go down in memory as y
    // goes up.
    PixelBlock(int minX, int minY, int rows, unsigned columns, __m512i laneOffsets, const Framebuffer& fb)
        : columns_(columns), rows_(rows), laneOffsets_(laneOffsets),
          firstPixel_(static_cast<std::size_t>(fb.height() - 1 - minY) * static_cast<std::size_t>(fb.width()) +
                      static_cast<std::size_t>(minX)),
          width_(static_cast<std::size_t>(fb.width())) {}

    // The lanes of `covered` loaded from `buffer`, the others zero. One gather: it measured
    // faster than a masked load per row, which stalls behind the previous triangle's stores.
    __m512i load(const std::uint32_t* buffer, __mmask16 covered) const {
        return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), covered, laneOffsets_, buffer + firstPixel_, 4);
    }
    // A masked store per row (a scatter measured slower).
    void store(std::uint32_t* buffer, __mmask16 covered, __m512i values) const {
        for (int row = 0; row < rows_; ++row) {
            const __mmask16 lanes = covered & rowLanes(row);
            if (lanes) _mm512_mask_storeu_epi32(laneZero(buffer, row), lanes, values);
        }
    }

private:
    __mmask16 rowLanes(int row) const {
        return static_cast<__mmask16>(((1u << columns_) - 1) << (static_cast<unsigned>(row) * columns_));
    }
    // Where lane 0 would be for the lanes of `row` to land on their pixels of `buffer`. Formed
    // as an integer: it may lie before the buffer, where only masked-off lanes point.
    std::uint32_t* laneZero(std::uint32_t* buffer, int row) const {
        const std::uint32_t* rowStart = buffer + firstPixel_ - static_cast<std::size_t>(row) * width_;
        return reinterpret_cast<std::uint32_t*>(reinterpret_cast<std::uintptr_t>(rowStart) -
                                                sizeof(std::uint32_t) * static_cast<unsigned>(row) * columns_);
    }

    unsigned columns_;
    int rows_;
    __m512i laneOffsets_;
    std::size_t firstPixel_, width_;
};

}  // namespace

void shadeSpanAvx512(const RasterTriangle& t, int row, int begin, int end, Framebuffer& fb,
                     FragmentCounts& counts) {
    const std::size_t offset = static_cast<std::size_t>(fb.height() - 1 - row) * static_cast<std::size_t>(fb.width());
    std::uint32_t* color = fb.color().data() + offset;
    std::uint32_t* depth = fb.depth().data() + offset;
    const __m512 y = _mm512_set1_ps(static_cast<float>(row));
    const TriangleLanes lanes(t);
    std::uint64_t passed = 0;
    // Blocks aligned to cache lines (the buffers are): a block across two lines made every
    // masked load and store touch both, a third of a dense frame. The first block starts at
    // the line holding `begin`, its lanes before it masked off.
    const int first = begin - static_cast<int>((offset + static_cast<std::size_t>(begin)) % 16);
    for (int px = first; px <= end; px += 16) {
        const int remaining = end - px + 1;
        __mmask16 mask = remaining >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << remaining) - 1);
        if (px < begin) mask &= static_cast<__mmask16>(~((1u << (begin - px)) - 1));
        const __m512 x = _mm512_cvtepi32_ps(_mm512_add_epi32(_mm512_set1_epi32(px), laneIndex()));
        if (t.state.depthTest) {
            const __m512i z = lanes.depth24(x, y);
            const __m512i stored = _mm512_maskz_loadu_epi32(mask, depth + px);
            mask = depthPassMask(t.state.depthFunc, mask, z, stored);
            if (t.state.depthWrite) _mm512_mask_storeu_epi32(depth + px, mask, z);
        }
        if (mask == 0) continue;
        passed += static_cast<unsigned>(std::popcount(static_cast<unsigned>(mask)));
        _mm512_mask_storeu_epi32(color + px, mask, lanes.rgba(x, y));
    }
    counts.fragments += static_cast<std::uint64_t>(end - begin + 1);
    counts.passed += passed;
}

bool shadeNarrowTriangleAvx512(const RasterTriangle& t, const PixelRect& area, Framebuffer& fb,
                               FragmentCounts& counts) {
    const int width = area.maxX - area.minX + 1;
    if (width > 16) return false;
    const unsigned columns = std::bit_ceil(static_cast<unsigned>(width));
    const int columnBits = std::countr_zero(columns);
    const int blockRows = 16 >> columnBits;
    // Edge values in 32-bit lanes: they hold every value of every block when the steps and the
    // values at the area's corners (the extremes of a linear function) are this small, as for
    // any triangle this narrow that is not also huge.
    constexpr std::int64_t kStepLimit = std::int64_t{1} << 25, kValueLimit = std::int64_t{1} << 29;
    const int height = area.maxY - area.minY + 1;  // at most a tile's
    for (const EdgeFunction& edge : t.edges) {
        if (std::abs(edge.stepX) >= kStepLimit || std::abs(edge.stepY) >= kStepLimit) return false;
        const std::int64_t corner = edge.at(area.minX, area.minY);
        const std::int64_t acrossX = edge.stepX * (width - 1), acrossY = edge.stepY * (height - 1);
        for (const std::int64_t value : {corner, corner + acrossX, corner + acrossY, corner + acrossX + acrossY}) {
            if (std::abs(value) >= kValueLimit) return false;
        }
    }
    const __m512i dx = _mm512_and_epi32(laneIndex(), _mm512_set1_epi32(static_cast<int>(columns - 1)));
    const __m512i dy = _mm512_srl_epi32(laneIndex(), _mm_cvtsi32_si128(columnBits));
    const __m512 x = _mm512_cvtepi32_ps(_mm512_add_epi32(_mm512_set1_epi32(area.minX), dx));
    const __mmask16 inColumns = _mm512_cmplt_epi32_mask(dx, _mm512_set1_epi32(width));
    const __m512i laneOffsets = _mm512_sub_epi32(dx, _mm512_mullo_epi32(dy, _mm512_set1_epi32(fb.width())));
    __m512i stepX[3], stepY[3];
    for (int k = 0; k < 3; ++k) {
        stepX[k] = _mm512_mullo_epi32(dx, _mm512_set1_epi32(static_cast<int>(t.edges[k].stepX)));
        stepY[k] = _mm512_mullo_epi32(dy, _mm512_set1_epi32(static_cast<int>(t.edges[k].stepY)));
    }
    const TriangleLanes lanes(t);
    std::uint64_t fragments = 0, passedCount = 0;
    for (int top = area.minY; top <= area.maxY; top += blockRows) {
        const int rows = std::min(blockRows, area.maxY - top + 1);
        __m512i outside = _mm512_setzero_si512();  // sign bit set where any edge is negative
        for (int k = 0; k < 3; ++k) {
            const __m512i first = _mm512_set1_epi32(static_cast<int>(t.edges[k].at(area.minX, top)));
            outside = _mm512_or_si512(outside, _mm512_add_epi32(first, _mm512_add_epi32(stepX[k], stepY[k])));
        }
        const __mmask16 inBlock = inColumns & _mm512_cmplt_epi32_mask(dy, _mm512_set1_epi32(rows));
        const __mmask16 covered = _mm512_mask_cmpge_epi32_mask(inBlock, outside, _mm512_setzero_si512());
        if (covered == 0) continue;
        fragments += static_cast<unsigned>(std::popcount(static_cast<unsigned>(covered)));
        const PixelBlock block(area.minX, top, rows, columns, laneOffsets, fb);
        const __m512 y = _mm512_cvtepi32_ps(_mm512_add_epi32(_mm512_set1_epi32(top), dy));
        __mmask16 passed = covered;
        if (t.state.depthTest) {
            const __m512i z = lanes.depth24(x, y);
            passed = depthPassMask(t.state.depthFunc, covered, z, block.load(fb.depth().data(), covered));
            if (t.state.depthWrite) block.store(fb.depth().data(), passed, z);
            if (passed == 0) continue;
        }
        passedCount += static_cast<unsigned>(std::popcount(static_cast<unsigned>(passed)));
        block.store(fb.color().data(), passed, lanes.rgba(x, y));
    }
    counts.fragments += fragments;
    counts.passed += passedCount;
    return true;
}

}  // namespace glrenderer
