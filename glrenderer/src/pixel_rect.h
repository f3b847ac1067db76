#pragma once
#include <algorithm>
#include <cstdint>

#include "glrenderer/fragment_ops.h"

namespace glrenderer {

struct PixelRect {
    int minX, maxX, minY, maxY;  // inclusive
};

// The pixels a draw may write, in internal (y-down) rows: the framebuffer's, cut to the scissor
// box when it is enabled (empty, minX > maxX or minY > maxY, when they do not meet). The scissor
// test is done here, on the primitives' bounds, never per fragment.
inline PixelRect drawableRect(const ScissorBox& scissor, int width, int height) {
    if (!scissor.enabled) return {0, width - 1, 0, height - 1};
    // In 64 bits: a box may start anywhere an int reaches and be as wide.
    const std::int64_t left = scissor.x, bottom = scissor.y;
    const std::int64_t right = left + scissor.width - 1, top = bottom + scissor.height - 1;
    // Lows within [0, size], highs within [-1, size - 1]: a box outside gives an empty rect.
    const auto low = [](std::int64_t v, int size) { return static_cast<int>(std::clamp<std::int64_t>(v, 0, size)); };
    const auto high = [](std::int64_t v, int size) {
        return static_cast<int>(std::clamp<std::int64_t>(v, -1, size - 1));
    };
    return {low(left, width), high(right, width), low(height - 1 - top, height), high(height - 1 - bottom, height)};
}

}  // namespace glrenderer
