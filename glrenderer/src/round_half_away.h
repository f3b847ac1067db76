#pragma once
#include <cstdint>

namespace glrenderer {

// The reference's float-to-int rounding for lines and points (not triangles): add or subtract
// a half in float arithmetic, then truncate, so halves round away from zero (and the float
// addition itself may round, e.g. 0.49999997 becomes 1).
inline std::int64_t roundHalfAway(float value) {
    return static_cast<std::int64_t>(value >= 0.0f ? value + 0.5f : value - 0.5f);
}

}  // namespace glrenderer
