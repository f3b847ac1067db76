#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "glrenderer/draw_state.h"
#include "glrenderer/round_to_even.h"
#include "cpu_features.h"

namespace glrenderer {

// One lane, in plain C++: the lane operations of the fragment stage (fragment_stage.h) for any
// CPU. min and max follow x86's minps/maxps (the second operand when either is NaN), so that the
// stage's clamps give the same bits at every width.
struct ScalarLanes {
    static constexpr int kCount = 1;
    static constexpr bool kCheapMasks = true;
    static constexpr bool kNarrowBlocks = false;  // a block of one lane is a span
    static constexpr bool kTwoRowBlocks = false;
    static constexpr bool kPackedBlocks = false;
    static constexpr std::string_view kName = "scalar";
    using Float = float;
    using Int = std::uint32_t;
    using Mask = bool;

    static Float floats(float v) { return v; }
    static Int ints(int v) { return static_cast<Int>(v); }
    static Int laneIndex() { return 0; }

    static Float fma(Float a, Float b, Float c) { return std::fma(a, b, c); }
    static Float mul(Float a, Float b) { return a * b; }
    static Float add(Float a, Float b) { return a + b; }
    static Float sub(Float a, Float b) { return a - b; }
    // LLVM's fmuladd, as the reference's JIT emits it: fused only on CPUs with FMA.
    static Float multiplyAdd(Float a, Float b, Float c) {
        static const bool fused = cpuHasFma();
        return fused ? std::fma(a, b, c) : a * b + c;
    }
    static Float floor(Float v) { return std::floor(v); }
    static Float div(Float a, Float b) { return a / b; }
    static Float min(Float a, Float b) { return a < b ? a : b; }
    static Float max(Float a, Float b) { return a > b ? a : b; }
    static Float sqrt(Float v) { return std::sqrt(v); }
    static Float abs(Float v) { return std::fabs(v); }
    // Ordered comparisons of floats: false where either is NaN.
    static Mask lessThan(Float a, Float b) { return a < b; }
    static Mask lessEqual(Float a, Float b) { return a <= b; }
    static Mask equal(Float a, Float b) { return a == b; }
    static Mask isNan(Float v) { return v != v; }
    static Float select(Mask m, Float ifSet, Float ifClear) { return m ? ifSet : ifClear; }
    static Float toFloat(Int v) { return static_cast<Float>(static_cast<std::int32_t>(v)); }
    // As cvtps2dq: ties to even; NaN and values out of range give INT_MIN.
    static Int roundToInt(Float v) {
        if (!(std::fabs(v) < 2147483648.0f)) return 0x80000000u;
        return static_cast<Int>(static_cast<std::int32_t>(roundToEven(v)));
    }
    // Towards zero, as cvttps2dq: NaN and values out of range give INT_MIN.
    static Int truncateToInt(Float v) {
        return std::isfinite(v) && std::fabs(v) < 2147483648.0f ? static_cast<Int>(static_cast<std::int32_t>(v))
                                                                : 0x80000000u;
    }
    static Int bitsOf(Float v) { return std::bit_cast<Int>(v); }
    static Float fromBits(Int v) { return std::bit_cast<Float>(v); }

    static Int add(Int a, Int b) { return a + b; }
    static Int sub(Int a, Int b) { return a - b; }
    static Int mul(Int a, Int b) { return a * b; }
    // Texture sampling's integer steps (fragment_texture.h).
    static Int minInt(Int a, Int b) { return static_cast<std::int32_t>(a) < static_cast<std::int32_t>(b) ? a : b; }
    static Int maxInt(Int a, Int b) { return static_cast<std::int32_t>(a) > static_cast<std::int32_t>(b) ? a : b; }
    template <int N>
    static Int shiftRightSigned(Int v) {
        return static_cast<Int>(static_cast<std::int32_t>(v) >> N);
    }
    template <int N>
    static Int shiftRightUnsigned(Int v) {
        return v >> N;
    }
    static Mask lessThan(Int a, Int b) { return static_cast<std::int32_t>(a) < static_cast<std::int32_t>(b); }
    static Int select(Mask m, Int ifSet, Int ifClear) { return m ? ifSet : ifClear; }
    static Mask greaterThan(Float a, Float b) { return a > b; }
    // The two 16-bit fields (each 0-255) of words a and b lerped with weight w (0-255):
    // a + ((w * (b - a) + 128) >> 8) per field, the rounding of llvmpipe's pmulhrsw.
    static Int lerpFields(Int w, Int a, Int b) {
        Int out = 0;
        for (int shift = 0; shift < 32; shift += 16) {
            const auto x = static_cast<std::int32_t>((a >> shift) & 0xFFFF),
                       y = static_cast<std::int32_t>((b >> shift) & 0xFFFF);
            const std::int32_t lerped = x + ((static_cast<std::int32_t>(w) * (y - x) + 128) >> 8);
            out |= static_cast<Int>(lerped) << shift;
        }
        return out;
    }
    static Int gather(const std::uint32_t* base, Int offset, Mask m) { return m ? base[offset] : 0; }
    static Int lookup16(const std::uint32_t* table, Int index) { return table[index]; }  // index 0-15
    static Int bitAnd(Int a, Int b) { return a & b; }
    static Int bitOr(Int a, Int b) { return a | b; }
    static Int bitXor(Int a, Int b) { return a ^ b; }
    static Mask either(Mask a, Mask b) { return a || b; }
    static Float loadFloats(const float* lanes) { return *lanes; }
    static void storeFloats(float* lanes, Float v) { *lanes = v; }
    static Int minUnsigned(Int a, Int b) { return a < b ? a : b; }
    static Int maxUnsigned(Int a, Int b) { return a > b ? a : b; }
    // Per 16-bit half: the low 16 bits of the product, the unsigned minimum, a logical shift
    // right by 8.
    static Int mulLow16(Int a, Int b) { return ((a & 0xFFFF) * (b & 0xFFFF) & 0xFFFF) | ((a >> 16) * (b >> 16) << 16); }
    static Int shiftRight16By8(Int v) { return (v >> 8) & 0x00FF00FF; }
    static Int minUnsigned16(Int a, Int b) {
        return std::min(a & 0xFFFF, b & 0xFFFF) | std::min(a & 0xFFFF0000, b & 0xFFFF0000);
    }
    template <int N>
    static Int shiftLeft(Int v) {
        return v << N;
    }
    static Int shiftRight(Int v, int n) { return v >> n; }

    // Lane 0 when first <= 0 <= last.
    static Mask lanesBetween(int first, int last) { return first <= 0 && last >= 0; }
    static Mask both(Mask a, Mask b) { return a && b; }
    static Mask butNot(Mask a, Mask b) { return a && !b; }
    static bool none(Mask m) { return !m; }
    static bool all(Mask m) { return m; }
    static unsigned count(Mask m) { return m ? 1u : 0u; }
    static Mask compare(CompareFunc func, Mask active, Int incoming, Int stored) {
        switch (func) {
        case CompareFunc::Never: return false;
        case CompareFunc::Less: return active && incoming < stored;
        case CompareFunc::Equal: return active && incoming == stored;
        case CompareFunc::LessEqual: return active && incoming <= stored;
        case CompareFunc::Greater: return active && incoming > stored;
        case CompareFunc::NotEqual: return active && incoming != stored;
        case CompareFunc::GreaterEqual: return active && incoming >= stored;
        case CompareFunc::Always: return active;
        }
        return false;
    }

    static Int load(const std::uint32_t* pixel, Mask m) { return m ? *pixel : 0; }
    static void store(std::uint32_t* pixel, Mask m, Int v) {
        if (m) *pixel = v;
    }
};

}  // namespace glrenderer
