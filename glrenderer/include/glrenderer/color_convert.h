#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec4.hpp>

namespace glrenderer {

// Float to 8-bit as the reference converts it: clamp to [0, 1], then round float(v * 255) to
// nearest, ties to even (the default rounding mode; std::nearbyint honours it). NaN becomes 0.
inline std::uint8_t toUnorm8(float value) {
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(std::nearbyint(clamped * 255.0f));
}

// R, G, B, A bytes in memory order packed into one word (little endian: R in the low byte).
inline std::uint32_t packRgba8(const glm::vec4& color) {
    return std::uint32_t{toUnorm8(color.r)} | std::uint32_t{toUnorm8(color.g)} << 8 |
           std::uint32_t{toUnorm8(color.b)} << 16 | std::uint32_t{toUnorm8(color.a)} << 24;
}

inline constexpr std::uint32_t kDepthMax24 = 0xFFFFFF;

// Depth in [0, 1] to the 24-bit buffer value: round float(z * 16777215) to nearest even.
inline std::uint32_t toDepth24(float depth) {
    const float clamped = depth > 0.0f ? std::min(depth, 1.0f) : 0.0f;
    return static_cast<std::uint32_t>(std::nearbyint(clamped * 16777215.0f));
}

}  // namespace glrenderer
