#pragma once
#include <immintrin.h>

#include <glm/vec4.hpp>

namespace mygl {

// Clamps state values to [0, 1] as the reference's CLAMP does: NaN becomes 0.
template <class T>
constexpr T clampToUnit(T v) {
    return v > T(0) ? (v > T(1) ? T(1) : v) : T(0);
}

// The reference's vertex stage saturates colours with max(0, c) then min(., 1), where a NaN
// operand gives way to the second one: NaN stays NaN, then becomes 1. SSE's max and min do
// exactly that, four components at once.
inline glm::vec4 saturate(const glm::vec4& c) {
    glm::vec4 out;
    _mm_storeu_ps(&out.x, _mm_min_ps(_mm_max_ps(_mm_setzero_ps(), _mm_loadu_ps(&c.x)), _mm_set1_ps(1.0f)));
    return out;
}

}  // namespace mygl
