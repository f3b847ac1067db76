#pragma once
#include <cstdint>

#include "triangle_setup.h"

namespace glrenderer {

// The reference's float-to-int rounding for lines and points (not triangles): add or subtract
// a half in float arithmetic, then truncate, so halves round away from zero (and the float
// addition itself may round, e.g. 0.49999997 becomes 1).
inline std::int64_t roundHalfAway(float value) {
    return static_cast<std::int64_t>(value >= 0.0f ? value + 0.5f : value - 0.5f);
}

// Fixed point at 1/256 pixel, rounded as the reference's lines and points round (unlike its
// triangles): add or subtract a half in float, then truncate. Halves go away from zero.
inline std::int64_t toFixedHalfAway(float pixels) { return roundHalfAway(pixels * kSubpixelScale); }

}  // namespace glrenderer
