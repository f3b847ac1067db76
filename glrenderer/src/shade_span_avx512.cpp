// The span shader for CPUs with AVX-512F, 16 pixels per step. Compiled with -mavx512f -mfma and
// called only after cpuHasAvx512(). Each lane performs the scalar kernel's operations in the
// same order, so the bits match shadeSpanScalar (and the AVX2 shader) exactly; what changes is
// the width and the mask registers, which make the partial blocks as cheap as whole ones.
#include <immintrin.h>

#include <bit>

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

}  // namespace

void shadeSpanAvx512(const RasterTriangle& t, int row, int begin, int end, Framebuffer& fb,
                     FragmentCounts& counts) {
    const std::size_t offset = static_cast<std::size_t>(fb.height() - 1 - row) * static_cast<std::size_t>(fb.width());
    std::uint32_t* color = fb.color().data() + offset;
    std::uint32_t* depth = fb.depth().data() + offset;
    const __m512 y = _mm512_set1_ps(static_cast<float>(row));
    const __m512i laneIndex = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const PlaneLanes depthPlane(t.depth), invW(t.invW);
    const PlaneLanes r(t.color[0]), g(t.color[1]), b(t.color[2]), a(t.color[3]);
    const __m512i flatColor = _mm512_set1_epi32(static_cast<int>(t.flatColor));
    std::uint64_t passed = 0;
    for (int px = begin; px <= end; px += 16) {
        const int remaining = end - px + 1;
        __mmask16 mask = remaining >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << remaining) - 1);
        const __m512 x = _mm512_cvtepi32_ps(_mm512_add_epi32(_mm512_set1_epi32(px), laneIndex));
        if (t.state.depthTest) {
            const __m512i z = toDepth24(depthPlane.at(x, y));
            const __m512i stored = _mm512_maskz_loadu_epi32(mask, depth + px);
            mask = depthPassMask(t.state.depthFunc, mask, z, stored);
            if (t.state.depthWrite) _mm512_mask_storeu_epi32(depth + px, mask, z);
        }
        if (mask == 0) continue;
        passed += static_cast<unsigned>(std::popcount(static_cast<unsigned>(mask)));
        __m512i rgba = flatColor;
        if (t.state.smooth) {
            const __m512 w = _mm512_div_ps(_mm512_set1_ps(1.0f), invW.at(x, y));
            rgba = _mm512_or_si512(
                _mm512_or_si512(fragmentToUnorm8(_mm512_mul_ps(r.at(x, y), w)),
                                _mm512_slli_epi32(fragmentToUnorm8(_mm512_mul_ps(g.at(x, y), w)), 8)),
                _mm512_or_si512(_mm512_slli_epi32(fragmentToUnorm8(_mm512_mul_ps(b.at(x, y), w)), 16),
                                _mm512_slli_epi32(fragmentToUnorm8(_mm512_mul_ps(a.at(x, y), w)), 24)));
        }
        _mm512_mask_storeu_epi32(color + px, mask, rgba);
    }
    counts.fragments += static_cast<std::uint64_t>(end - begin + 1);
    counts.passed += passed;
}

}  // namespace glrenderer
