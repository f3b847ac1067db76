#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/vec4.hpp>

#include "glrenderer/round_to_even.h"

namespace glrenderer {

// Float to 8-bit as the reference converts glClear's color: clamp to [0, 1], then round
// float(v * 255) to nearest, ties to even (the default rounding mode). NaN becomes 0.
inline std::uint8_t toUnorm8(float value) {
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(roundToEven(clamped * 255.0f));
}

// Float to 8-bit as the reference's fragment pipeline converts shaded colors: clamp, scale by
// 255/256, and let adding 2^15 round the value onto the float grid of 1/256 steps (ties to
// even); the byte is the low mantissa bits. Differs from toUnorm8 on exact ties of v * 255.
inline std::uint8_t fragmentToUnorm8(float value) {
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
    const float biased = clamped * (255.0f / 256.0f) + 32768.0f;
    std::uint32_t bits;
    std::memcpy(&bits, &biased, sizeof bits);
    return static_cast<std::uint8_t>(bits & 0xFF);
}

// R, G, B, A bytes in memory order packed into one word (little endian: R in the low byte).
inline std::uint32_t packRgba8(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
    return std::uint32_t{r} | std::uint32_t{g} << 8 | std::uint32_t{b} << 16 | std::uint32_t{a} << 24;
}

// glClear's color word.
inline std::uint32_t clearColorRgba8(const glm::vec4& c) {
    return packRgba8(toUnorm8(c.r), toUnorm8(c.g), toUnorm8(c.b), toUnorm8(c.a));
}

// A fragment's color word.
inline std::uint32_t fragmentRgba8(const glm::vec4& c) {
    return packRgba8(fragmentToUnorm8(c.r), fragmentToUnorm8(c.g), fragmentToUnorm8(c.b), fragmentToUnorm8(c.a));
}

inline constexpr std::uint32_t kDepthMax24 = 0xFFFFFF;

// glClear's depth: the clear value (a double in [0, 1]) times 16777215, rounded in double to
// nearest even.
inline std::uint32_t clearDepth24(double depth) {
    if (!(depth > 0.0)) return 0;
    if (depth >= 1.0) return kDepthMax24;
    return static_cast<std::uint32_t>(std::nearbyint(depth * 16777215.0));
}

// glClear's depth when the reference clears depth by drawing a quad (a scissor smaller than the
// window, or the stencil cleared with it under a partial write mask): the clear value as a
// float NDC z, (d * 2 - 1) * 0.5 + 0.5 in float, times 16777215 in float, rounded to nearest even.
inline std::uint32_t quadClearDepth24(double depth) {
    const float clamped = static_cast<float>(std::clamp(depth, 0.0, 1.0));
    const float window = (clamped * 2.0f - 1.0f) * 0.5f + 0.5f;
    return static_cast<std::uint32_t>(std::nearbyint(window * 16777215.0f));
}

}  // namespace glrenderer
