#pragma once
// Only for files compiled with -mavx2 -mfma, called after cpuHasAvx2Fma().
#include <immintrin.h>

#include <bit>
#include <cstdint>
#include <string_view>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// 8 lanes of AVX2: the lane operations of the fragment stage (fragment_stage.h). A mask is a
// vector of all-ones or zero lanes. Masked loads and stores are slow on some CPUs, so blocks
// whose lanes all lie inside the span use plain ones (kCheapMasks = false: loadWhole,
// storeWhole, select).
// `Evex`: the same lanes in a file compiled for AVX-512VL (fragment_paths_avx2_evex.cpp), where
// the compiler has 32 vector registers and EVEX encodings for the same code. A type of its own
// so that the two files' copies of these functions, compiled for different CPUs, never merge.
template <bool Evex>
struct Avx2LanesOf {
    static constexpr int kCount = 8;
    static constexpr bool kCheapMasks = false;
    // No 2D blocks for narrow triangles: they took more instructions than spans on triangles of
    // a pixel or two (callgrind, bench-tiny), and gathers are slow on several AVX2 CPUs.
    static constexpr bool kNarrowBlocks = false;
    // Keys that sample a level of detail walk rows in pairs, in blocks of 4 x 2 pixels: two
    // whole 2 x 2 quads (QuadLanes::TwoRows).
    static constexpr bool kTwoRowBlocks = true;
    // Tiny triangles packed into one block (packed_triangles.h): with AVX-512VL and CD, their
    // coverage found in 16 lanes of AVX-512 (__m512i below, only where Evex).
    static constexpr bool kPackedBlocks = Evex;
    static constexpr std::string_view kName = Evex ? "avx2-evex" : "avx2";
    using Float = __m256;
    using Int = __m256i;
    using Mask = __m256i;

    static Float floats(float v) { return _mm256_set1_ps(v); }
    static Int ints(int v) { return _mm256_set1_epi32(v); }
    static Int laneIndex() { return _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }

    static Float fma(Float a, Float b, Float c) { return _mm256_fmadd_ps(a, b, c); }
    static Float mul(Float a, Float b) { return _mm256_mul_ps(a, b); }
    static Float add(Float a, Float b) { return _mm256_add_ps(a, b); }
    static Float sub(Float a, Float b) { return _mm256_sub_ps(a, b); }
    static Float multiplyAdd(Float a, Float b, Float c) { return _mm256_fmadd_ps(a, b, c); }  // FMA: fused
    static Float floor(Float v) { return _mm256_floor_ps(v); }
    static Float div(Float a, Float b) { return _mm256_div_ps(a, b); }
    static Float min(Float a, Float b) { return _mm256_min_ps(a, b); }
    static Float max(Float a, Float b) { return _mm256_max_ps(a, b); }
    static Float sqrt(Float v) { return _mm256_sqrt_ps(v); }
    static Float abs(Float v) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), v); }
    // Ordered comparisons of floats: false where either is NaN.
    static Mask lessThan(Float a, Float b) { return _mm256_castps_si256(_mm256_cmp_ps(a, b, _CMP_LT_OQ)); }
    static Mask lessEqual(Float a, Float b) { return _mm256_castps_si256(_mm256_cmp_ps(a, b, _CMP_LE_OQ)); }
    static Mask equal(Float a, Float b) { return _mm256_castps_si256(_mm256_cmp_ps(a, b, _CMP_EQ_OQ)); }
    static Mask isNan(Float v) { return _mm256_castps_si256(_mm256_cmp_ps(v, v, _CMP_UNORD_Q)); }
    static Float select(Mask m, Float ifSet, Float ifClear) {
        return _mm256_blendv_ps(ifClear, ifSet, _mm256_castsi256_ps(m));
    }
    static Float toFloat(Int v) { return _mm256_cvtepi32_ps(v); }
    static Int roundToInt(Float v) { return _mm256_cvtps_epi32(v); }
    static Int truncateToInt(Float v) { return _mm256_cvttps_epi32(v); }
    static Int bitsOf(Float v) { return _mm256_castps_si256(v); }
    static Float fromBits(Int v) { return _mm256_castsi256_ps(v); }

    static Int add(Int a, Int b) { return _mm256_add_epi32(a, b); }
    static Int sub(Int a, Int b) { return _mm256_sub_epi32(a, b); }
    static Int mul(Int a, Int b) { return _mm256_mullo_epi32(a, b); }
    static Int bitAnd(Int a, Int b) { return _mm256_and_si256(a, b); }
    static Int bitOr(Int a, Int b) { return _mm256_or_si256(a, b); }
    static Int bitXor(Int a, Int b) { return _mm256_xor_si256(a, b); }
    static Mask either(Mask a, Mask b) { return _mm256_or_si256(a, b); }
    static Float loadFloats(const float* lanes) { return _mm256_loadu_ps(lanes); }
    static void storeFloats(float* lanes, Float v) { _mm256_storeu_ps(lanes, v); }
    static Int minUnsigned(Int a, Int b) { return _mm256_min_epu32(a, b); }
    // Per 16-bit half of each lane: the low 16 bits of the product, the unsigned minimum, a
    // logical shift right by 8.
    static Int mulLow16(Int a, Int b) { return _mm256_mullo_epi16(a, b); }
    static Int minUnsigned16(Int a, Int b) { return _mm256_min_epu16(a, b); }
    static Int shiftRight16By8(Int v) { return _mm256_srli_epi16(v, 8); }
    static Int maxUnsigned(Int a, Int b) { return _mm256_max_epu32(a, b); }
    static Int minInt(Int a, Int b) { return _mm256_min_epi32(a, b); }
    static Int maxInt(Int a, Int b) { return _mm256_max_epi32(a, b); }
    template <int N>
    static Int shiftRightSigned(Int v) {
        return _mm256_srai_epi32(v, N);
    }
    template <int N>
    static Int shiftRightUnsigned(Int v) {
        return _mm256_srli_epi32(v, N);
    }
    template <int N>
    static Int shiftLeft(Int v) {
        return _mm256_slli_epi32(v, N);
    }
    static Int shiftRight(Int v, int n) { return _mm256_srl_epi32(v, _mm_cvtsi32_si128(n)); }

    static Mask lessThan(Int a, Int b) { return _mm256_cmpgt_epi32(b, a); }
    static Mask notNegative(Int a) { return _mm256_cmpgt_epi32(a, _mm256_set1_epi32(-1)); }
    static Mask lanesBetween(int first, int last) {
        return _mm256_andnot_si256(_mm256_cmpgt_epi32(_mm256_set1_epi32(first), laneIndex()),
                                   _mm256_cmpgt_epi32(_mm256_set1_epi32(last + 1), laneIndex()));
    }
    static Mask both(Mask a, Mask b) { return _mm256_and_si256(a, b); }
    static Mask butNot(Mask a, Mask b) { return _mm256_andnot_si256(b, a); }
    static bool none(Mask m) { return _mm256_testz_si256(m, m); }
    static bool all(Mask m) { return _mm256_movemask_ps(_mm256_castsi256_ps(m)) == 0xFF; }
    static unsigned count(Mask m) {
        return static_cast<unsigned>(std::popcount(static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(m)))));
    }
    // Lanes of `active` where incoming passes against stored. Signed compares: depths are below
    // 2^24.
    static Mask compare(CompareFunc func, Mask active, Int incoming, Int stored) {
        const Int ones = _mm256_set1_epi32(-1);
        switch (func) {
        case CompareFunc::Never: return _mm256_setzero_si256();
        case CompareFunc::Less: return both(active, _mm256_cmpgt_epi32(stored, incoming));
        case CompareFunc::Equal: return both(active, _mm256_cmpeq_epi32(incoming, stored));
        case CompareFunc::LessEqual: return _mm256_andnot_si256(_mm256_cmpgt_epi32(incoming, stored), active);
        case CompareFunc::Greater: return both(active, _mm256_cmpgt_epi32(incoming, stored));
        case CompareFunc::NotEqual: return _mm256_andnot_si256(_mm256_cmpeq_epi32(incoming, stored), active);
        case CompareFunc::GreaterEqual: return _mm256_andnot_si256(_mm256_cmpgt_epi32(stored, incoming), active);
        case CompareFunc::Always: return both(active, ones);
        }
        return _mm256_setzero_si256();
    }

    static Int load(const std::uint32_t* pixels, Mask m) {
        return _mm256_maskload_epi32(reinterpret_cast<const int*>(pixels), m);
    }
    static void store(std::uint32_t* pixels, Mask m, Int v) {
        _mm256_maskstore_epi32(reinterpret_cast<int*>(pixels), m, v);
    }
    static Int loadWhole(const std::uint32_t* pixels) {
        return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pixels));
    }
    static void storeWhole(std::uint32_t* pixels, Int v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(pixels), v); }
    static Int select(Mask m, Int ifSet, Int ifClear) { return _mm256_blendv_epi8(ifClear, ifSet, m); }
    // The two 16-bit fields (each 0-255) of words a and b lerped with weights w (0-255):
    // a + ((w * (b - a) + 128) >> 8) per field with pmulhrsw, as llvmpipe's sampler does. The
    // result lies between a and b: no field carries into the next.
    // The weight takes the factor 128 (w * 128 < 2^15), one shift a weight instead of one a lerp.
    static Int lerpFields(Int w, Int a, Int b) {
        __m256i w16;
        if constexpr (Evex)  // one multiply (w < 256: the two products do not overlap)
            w16 = _mm256_mullo_epi32(w, _mm256_set1_epi32(0x00800080));
        else
            w16 = _mm256_or_si256(_mm256_slli_epi32(w, 7), _mm256_slli_epi32(w, 16 + 7));
        return _mm256_add_epi16(a, _mm256_mulhrs_epi16(w16, _mm256_sub_epi16(b, a)));
    }
    static Mask greaterThan(Float a, Float b) { return _mm256_castps_si256(_mm256_cmp_ps(a, b, _CMP_GT_OQ)); }
    // Lane 2k (even) or 2k + 1 (odd) in both lanes 2k and 2k + 1.
    static Float duplicateEven(Float v) { return _mm256_moveldup_ps(v); }
    static Float duplicateOdd(Float v) { return _mm256_movehdup_ps(v); }
    // Lanes 0-3 from `first`, lanes 4-7 from `second` (a block of two rows), as load and
    // loadWhole: a plain load for a half whose bit in `whole` (1: first, 2: second) is set.
    static Int loadHalves(const std::uint32_t* first, const std::uint32_t* second, Mask m, unsigned whole) {
        const __m128i low = loadHalf(first, _mm256_castsi256_si128(m), whole & 1u);
        return _mm256_inserti128_si256(_mm256_castsi128_si256(low),
                                       loadHalf(second, _mm256_extracti128_si256(m, 1), whole & 2u), 1);
    }
    // The lanes of `m` of v stored as loadHalves reads them.
    static void storeHalves(std::uint32_t* first, std::uint32_t* second, Mask m, Int v, unsigned whole) {
        storeHalf(first, _mm256_castsi256_si128(m), _mm256_castsi256_si128(v), whole & 1u);
        storeHalf(second, _mm256_extracti128_si256(m, 1), _mm256_extracti128_si256(v, 1), whole & 2u);
    }
    // Lanes 0-3 in lanes 0-3 and 4-7; lanes 0-3 and 4-7 exchanged.
    static Float firstHalfTwice(Float v) { return _mm256_permute2f128_ps(v, v, 0x00); }
    static Float swapHalves(Float v) { return _mm256_permute2f128_ps(v, v, 0x01); }
    // table[index] per lane, index 0-15: two permutes (one two-table permute with AVX-512VL),
    // where a gather of a 16-entry table is several times slower.
    static Int lookup16(const std::uint32_t* table, Int index) {
        const Int first = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(table));
        const Int second = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(table + 8));
        if constexpr (Evex) {
            return _mm256_permutex2var_epi32(first, index, second);  // bit 3 of the index picks the table
        } else {
            const Int low = _mm256_permutevar8x32_epi32(first, index),
                      high = _mm256_permutevar8x32_epi32(second, index);
            // Bit 3 of the index (8-15: the second half) as the sign bit a float blend reads.
            const __m256 upper = _mm256_castsi256_ps(_mm256_slli_epi32(index, 28));
            return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(low), _mm256_castsi256_ps(high), upper));
        }
    }
    // The lanes of `m` read at base[offsets[i]], the others zero.
    static Int gather(const std::uint32_t* base, Int offsets, Mask m) {
        return _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), reinterpret_cast<const int*>(base), offsets, m, 4);
    }

    // As Avx512Lanes' (with Evex only): lanes 0-7 of `compressed` (Avx512Lanes::compress) in
    // `into`'s lanes `at`; a scatter; whether a lane of `later` repeats one of `earlier`.
    static Int placeLanes(Int into, Mask at, __m512i compressed) {
        return _mm256_mask_expand_epi32(into, bits(at), _mm512_castsi512_si256(compressed));
    }
    static void scatter(std::uint32_t* base, Int offsets, Mask m, Int v) {
        _mm256_mask_i32scatter_epi32(base, bits(m), offsets, v, 4);
    }
    static bool repeatsAny(Int values, Mask earlier, Mask later) {
        const Int conflicts = _mm256_maskz_conflict_epi32(bits(later), values);
        return _mm256_mask_test_epi32_mask(bits(later), conflicts, _mm256_set1_epi32(bits(earlier))) != 0;
    }

private:
    static __mmask8 bits(Mask m) { return static_cast<__mmask8>(_mm256_movemask_ps(_mm256_castsi256_ps(m))); }
    static __m128i loadHalf(const std::uint32_t* pixels, __m128i m, bool whole) {
        if (whole) return _mm_loadu_si128(reinterpret_cast<const __m128i*>(pixels));
        return _mm_maskload_epi32(reinterpret_cast<const int*>(pixels), m);
    }
    static void storeHalf(std::uint32_t* pixels, __m128i m, __m128i v, bool whole) {
        const int lanes = _mm_movemask_ps(_mm_castsi128_ps(m));
        if (lanes == 0) return;
        if (!whole) return _mm_maskstore_epi32(reinterpret_cast<int*>(pixels), m, v);
        auto* at = reinterpret_cast<__m128i*>(pixels);
        _mm_storeu_si128(at, lanes == 0xF ? v : _mm_blendv_epi8(_mm_loadu_si128(at), v, m));
    }
};

using Avx2Lanes = Avx2LanesOf<false>;

}  // namespace glrenderer
