#pragma once
// Only for files compiled with -mavx512f -mavx512bw -mavx512cd -mfma, called after cpuHasAvx512().
#include <immintrin.h>

#include <bit>
#include <cstdint>
#include <string_view>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// 16 lanes of AVX-512F, BW and CD: the lane operations of the fragment stage (fragment_stage.h). Masks are
// mask registers, which make partial blocks as cheap as whole ones (kCheapMasks).
struct Avx512Lanes {
    static constexpr int kCount = 16;
    static constexpr bool kCheapMasks = true;
    static constexpr bool kNarrowBlocks = true;   // narrow triangles in 2D blocks of lanes
    static constexpr bool kTwoRowBlocks = false;  // keys with a level of detail take the AVX2 paths
    static constexpr bool kPackedBlocks = true;   // tiny triangles' fragments packed into one block
    static constexpr std::string_view kName = "avx512";
    using Float = __m512;
    using Int = __m512i;
    using Mask = __mmask16;

    static Float floats(float v) { return _mm512_set1_ps(v); }
    static Int ints(int v) { return _mm512_set1_epi32(v); }
    // A function, not a constant: a static initializer would run AVX-512 code on any CPU.
    static Int laneIndex() { return _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }

    static Float fma(Float a, Float b, Float c) { return _mm512_fmadd_ps(a, b, c); }
    static Float mul(Float a, Float b) { return _mm512_mul_ps(a, b); }
    static Float add(Float a, Float b) { return _mm512_add_ps(a, b); }
    static Float sub(Float a, Float b) { return _mm512_sub_ps(a, b); }
    static Float multiplyAdd(Float a, Float b, Float c) { return _mm512_fmadd_ps(a, b, c); }  // FMA: fused
    static Float floor(Float v) { return _mm512_roundscale_ps(v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
    static Float div(Float a, Float b) { return _mm512_div_ps(a, b); }
    static Float min(Float a, Float b) { return _mm512_min_ps(a, b); }
    static Float max(Float a, Float b) { return _mm512_max_ps(a, b); }
    static Float sqrt(Float v) { return _mm512_sqrt_ps(v); }
    static Float abs(Float v) { return _mm512_abs_ps(v); }
    // Ordered comparisons of floats: false where either is NaN.
    static Mask lessThan(Float a, Float b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    static Mask lessEqual(Float a, Float b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
    static Mask equal(Float a, Float b) { return _mm512_cmp_ps_mask(a, b, _CMP_EQ_OQ); }
    static Mask isNan(Float v) { return _mm512_cmp_ps_mask(v, v, _CMP_UNORD_Q); }
    static Float select(Mask m, Float ifSet, Float ifClear) { return _mm512_mask_blend_ps(m, ifClear, ifSet); }
    static Float toFloat(Int v) { return _mm512_cvtepi32_ps(v); }
    static Int roundToInt(Float v) { return _mm512_cvtps_epi32(v); }
    static Int truncateToInt(Float v) { return _mm512_cvttps_epi32(v); }
    static Int bitsOf(Float v) { return _mm512_castps_si512(v); }
    static Float fromBits(Int v) { return _mm512_castsi512_ps(v); }

    static Int add(Int a, Int b) { return _mm512_add_epi32(a, b); }
    static Int sub(Int a, Int b) { return _mm512_sub_epi32(a, b); }
    static Int mul(Int a, Int b) { return _mm512_mullo_epi32(a, b); }
    static Int bitAnd(Int a, Int b) { return _mm512_and_epi32(a, b); }
    static Int bitOr(Int a, Int b) { return _mm512_or_epi32(a, b); }
    static Int bitXor(Int a, Int b) { return _mm512_xor_epi32(a, b); }
    static Mask either(Mask a, Mask b) { return a | b; }
    static Float loadFloats(const float* lanes) { return _mm512_loadu_ps(lanes); }
    static void storeFloats(float* lanes, Float v) { _mm512_storeu_ps(lanes, v); }
    static Int minUnsigned(Int a, Int b) { return _mm512_min_epu32(a, b); }
    // Per 16-bit half of each lane (AVX-512BW): the low 16 bits of the product, the unsigned
    // minimum, a logical shift right by 8.
    static Int mulLow16(Int a, Int b) { return _mm512_mullo_epi16(a, b); }
    static Int minUnsigned16(Int a, Int b) { return _mm512_min_epu16(a, b); }
    static Int shiftRight16By8(Int v) { return _mm512_srli_epi16(v, 8); }
    static Int maxUnsigned(Int a, Int b) { return _mm512_max_epu32(a, b); }
    static Int minInt(Int a, Int b) { return _mm512_min_epi32(a, b); }
    static Int maxInt(Int a, Int b) { return _mm512_max_epi32(a, b); }
    template <int N>
    static Int shiftRightSigned(Int v) {
        return _mm512_srai_epi32(v, N);
    }
    template <int N>
    static Int shiftRightUnsigned(Int v) {
        return _mm512_srli_epi32(v, N);
    }
    template <int N>
    static Int shiftLeft(Int v) {
        return _mm512_slli_epi32(v, N);
    }
    static Int shiftRight(Int v, int n) { return _mm512_srl_epi32(v, _mm_cvtsi32_si128(n)); }

    static Mask lessThan(Int a, Int b) { return _mm512_cmplt_epi32_mask(a, b); }
    static Int select(Mask m, Int ifSet, Int ifClear) { return _mm512_mask_blend_epi32(m, ifClear, ifSet); }
    // As Avx2Lanes::lerpFields (pmulhrsw at this width is AVX-512BW).
    static Int lerpFields(Int w, Int a, Int b) {
        const __m512i w16 = _mm512_or_si512(_mm512_slli_epi32(w, 7), _mm512_slli_epi32(w, 16 + 7));
        return _mm512_add_epi16(a, _mm512_mulhrs_epi16(w16, _mm512_sub_epi16(b, a)));
    }
    static Mask greaterThan(Float a, Float b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    // Lane 2k (even) or 2k + 1 (odd) in both lanes 2k and 2k + 1.
    static Float duplicateEven(Float v) { return _mm512_moveldup_ps(v); }
    static Float duplicateOdd(Float v) { return _mm512_movehdup_ps(v); }
    static Mask notNegative(Int a) { return _mm512_cmpge_epi32_mask(a, _mm512_setzero_si512()); }
    static Mask lanesBetween(int first, int last) {
        const unsigned upTo = last >= 15 ? 0xFFFFu : last < 0 ? 0u : (2u << last) - 1;
        const unsigned from = first <= 0 ? 0xFFFFu : first > 15 ? 0u : 0xFFFFu << first;
        return static_cast<Mask>(upTo & from);
    }
    static Mask both(Mask a, Mask b) { return a & b; }
    // Lane i of `m` in lane i + count (0 <= count < 16), the lanes below count clear.
    static Mask moveLanesUp(Mask m, int count) { return static_cast<Mask>(m << count); }
    static Mask butNot(Mask a, Mask b) { return static_cast<Mask>(a & ~b); }
    static bool none(Mask m) { return m == 0; }
    static bool all(Mask m) { return m == 0xFFFF; }
    static unsigned count(Mask m) { return static_cast<unsigned>(std::popcount(static_cast<unsigned>(m))); }
    // Lanes of `active` where incoming passes against stored (depths are below 2^24).
    static Mask compare(CompareFunc func, Mask active, Int incoming, Int stored) {
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

    static Int load(const std::uint32_t* pixels, Mask m) { return _mm512_maskz_loadu_epi32(m, pixels); }
    static void store(std::uint32_t* pixels, Mask m, Int v) { _mm512_mask_storeu_epi32(pixels, m, v); }
    // table[index] per lane, index 0-15: one permute.
    static Int lookup16(const std::uint32_t* table, Int index) {
        return _mm512_permutexvar_epi32(index, _mm512_loadu_si512(table));
    }
    // The lanes of `m` read at base[offsets[i]], the others zero.
    static Int gather(const std::uint32_t* base, Int offsets, Mask m) {
        return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), m, offsets, base, 4);
    }
    // v's lanes of `m` written at base[offsets[i]].
    static void scatter(std::uint32_t* base, Int offsets, Mask m, Int v) {
        _mm512_mask_i32scatter_epi32(base, m, offsets, v, 4);
    }
    // The lanes `from` of `values`, in order, from lane 0; and `into` with such lanes in its
    // lanes `at` (as many). In registers: their memory forms are slow on Zen 4.
    static Int compress(Int values, Mask from) { return _mm512_maskz_compress_epi32(from, values); }
    static Int placeLanes(Int into, Mask at, Int compressed) { return _mm512_mask_expand_epi32(into, at, compressed); }
    // Whether a lane of `later` holds the value of a lane of `earlier`, all of whose lanes lie
    // below those of `later` (AVX-512CD's conflict detection: lane i's bits are the lanes below
    // it of equal value).
    static bool repeatsAny(Int values, Mask earlier, Mask later) {
        const Int conflicts = _mm512_maskz_conflict_epi32(later, values);
        return _mm512_mask_test_epi32_mask(later, conflicts, _mm512_set1_epi32(earlier)) != 0;
    }
};

}  // namespace glrenderer
