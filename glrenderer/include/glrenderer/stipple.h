#pragma once
// glLineStipple and glPolygonStipple with their enables (issue 16).
#include <array>
#include <cstdint>

namespace glrenderer {

// The line stipple: bit (n / factor) & 15 of the pattern says whether the n-th pixel along a
// line's major axis is drawn.
struct LineStipple {
    bool enabled = false;
    std::uint16_t pattern = 0xFFFF;
    std::uint16_t factor = 1;  // 1 to 256
    bool operator==(const LineStipple&) const = default;
};

// A 32 x 32 polygon stipple: row (y & 31) of the window (y from the bottom), its bit
// 31 - (x & 31) set where filled polygons are drawn.
using PolygonStipplePattern = std::array<std::uint32_t, 32>;

// The pattern as the pipeline keeps it: one copy per distinct pattern, alive as long as the
// process, so that a queued triangle may point at it. Null for the pattern of all ones (which
// stipples nothing). Programs set a handful of patterns, each kept once.
const PolygonStipplePattern* internPolygonStipple(const PolygonStipplePattern& pattern);

struct PolygonStipple {
    bool enabled = false;
    const PolygonStipplePattern* pattern = nullptr;  // interned; null: all ones, GL's initial pattern
    bool operator==(const PolygonStipple&) const = default;

    // Whether filled polygons lose any pixel to it.
    bool active() const { return enabled && pattern != nullptr; }
};

}  // namespace glrenderer
