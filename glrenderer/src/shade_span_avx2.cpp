// The span shader for CPUs with AVX2 and FMA, 8 pixels per step. Compiled with -mavx2 -mfma
// and called only after cpuHasAvx2Fma(). Every lane performs the scalar kernel's operations in
// the same order (the planes' two fmas, one IEEE division, the conversions' clamps), so the
// bits match shadeSpanScalar exactly.
#include <immintrin.h>

#include <bit>

#include "raster_span.h"

namespace glrenderer {
namespace {

struct PlaneLanes {
    __m256 a0, dadx, dady;
    explicit PlaneLanes(const AttributePlane& p)
        : a0(_mm256_set1_ps(p.a0)), dadx(_mm256_set1_ps(p.dadx)), dady(_mm256_set1_ps(p.dady)) {}
    __m256 at(__m256 x, __m256 y) const { return _mm256_fmadd_ps(dady, y, _mm256_fmadd_ps(dadx, x, a0)); }
};

__m256 clampUnit(__m256 v) {  // NaN and negatives to 0, like the scalar clamp
    return _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
}

__m256i toDepth24(__m256 z) {
    return _mm256_cvtps_epi32(_mm256_mul_ps(clampUnit(z), _mm256_set1_ps(16777215.0f)));
}

__m256i fragmentToUnorm8(__m256 v) {
    const __m256 biased = _mm256_add_ps(_mm256_mul_ps(clampUnit(v), _mm256_set1_ps(255.0f / 256.0f)),
                                        _mm256_set1_ps(32768.0f));
    return _mm256_and_si256(_mm256_castps_si256(biased), _mm256_set1_epi32(0xFF));
}

// Lanes where incoming passes against stored; depths are below 2^24, so signed compares work.
__m256i depthPassMask(CompareFunc func, __m256i incoming, __m256i stored) {
    const __m256i all = _mm256_set1_epi32(-1);
    switch (func) {
    case CompareFunc::Never: return _mm256_setzero_si256();
    case CompareFunc::Less: return _mm256_cmpgt_epi32(stored, incoming);
    case CompareFunc::Equal: return _mm256_cmpeq_epi32(incoming, stored);
    case CompareFunc::LessEqual: return _mm256_xor_si256(_mm256_cmpgt_epi32(incoming, stored), all);
    case CompareFunc::Greater: return _mm256_cmpgt_epi32(incoming, stored);
    case CompareFunc::NotEqual: return _mm256_xor_si256(_mm256_cmpeq_epi32(incoming, stored), all);
    case CompareFunc::GreaterEqual: return _mm256_xor_si256(_mm256_cmpgt_epi32(stored, incoming), all);
    case CompareFunc::Always: return all;
    }
    return _mm256_setzero_si256();
}

}  // namespace

void shadeSpanAvx2(const RasterTriangle& t, int row, int begin, int end, Framebuffer& fb,
                   FragmentCounts& counts) {
    const std::size_t offset = static_cast<std::size_t>(fb.height() - 1 - row) * static_cast<std::size_t>(fb.width());
    std::uint32_t* color = fb.color().data() + offset;
    std::uint32_t* depth = fb.depth().data() + offset;
    const __m256 y = _mm256_set1_ps(static_cast<float>(row));
    const __m256i laneIndex = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const PlaneLanes depthPlane(t.depth), invW(t.invW);
    const PlaneLanes r(t.color[0]), g(t.color[1]), b(t.color[2]), a(t.color[3]);
    const __m256i flatColor = _mm256_set1_epi32(static_cast<int>(t.flatColor));
    std::uint64_t passed = 0;
    for (int px = begin; px <= end; px += 8) {
        // Whole blocks use plain loads, blends and stores; only the last, partial block uses
        // masked loads and stores (which are slow on some CPUs) to stay inside the row.
        const bool whole = px + 7 <= end;
        const __m256i columns = _mm256_add_epi32(_mm256_set1_epi32(px), laneIndex);
        __m256i mask = whole ? _mm256_set1_epi32(-1) : _mm256_cmpgt_epi32(_mm256_set1_epi32(end + 1), columns);
        const __m256 x = _mm256_cvtepi32_ps(columns);
        auto* depthBlock = reinterpret_cast<__m256i*>(depth + px);
        auto* colorBlock = reinterpret_cast<__m256i*>(color + px);
        if (t.state.depthTest) {
            const __m256i z = toDepth24(depthPlane.at(x, y));
            const __m256i stored = whole ? _mm256_loadu_si256(depthBlock)
                                         : _mm256_maskload_epi32(reinterpret_cast<const int*>(depthBlock), mask);
            mask = _mm256_and_si256(mask, depthPassMask(t.state.depthFunc, z, stored));
            if (t.state.depthWrite) {
                if (whole) _mm256_storeu_si256(depthBlock, _mm256_blendv_epi8(stored, z, mask));
                else _mm256_maskstore_epi32(reinterpret_cast<int*>(depthBlock), mask, z);
            }
        }
        const unsigned lanes = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(mask)));
        if (lanes == 0) continue;
        passed += static_cast<unsigned>(std::popcount(lanes));
        __m256i rgba = flatColor;
        if (t.state.smooth) {
            __m256 red = r.at(x, y), green = g.at(x, y), blue = b.at(x, y), alpha = a.at(x, y);
            if (t.state.perspective) {
                const __m256 w = _mm256_div_ps(_mm256_set1_ps(1.0f), invW.at(x, y));
                red = _mm256_mul_ps(red, w), green = _mm256_mul_ps(green, w);
                blue = _mm256_mul_ps(blue, w), alpha = _mm256_mul_ps(alpha, w);
            }
            rgba = _mm256_or_si256(
                _mm256_or_si256(fragmentToUnorm8(red), _mm256_slli_epi32(fragmentToUnorm8(green), 8)),
                _mm256_or_si256(_mm256_slli_epi32(fragmentToUnorm8(blue), 16),
                                _mm256_slli_epi32(fragmentToUnorm8(alpha), 24)));
        }
        if (lanes == 0xFF) _mm256_storeu_si256(colorBlock, rgba);
        else if (whole) _mm256_storeu_si256(colorBlock, _mm256_blendv_epi8(_mm256_loadu_si256(colorBlock), rgba, mask));
        else _mm256_maskstore_epi32(reinterpret_cast<int*>(colorBlock), mask, rgba);
    }
    counts.fragments += static_cast<std::uint64_t>(end - begin + 1);
    counts.passed += passed;
}

}  // namespace glrenderer
