#pragma once
#include <xmmintrin.h>

#include <glm/vec4.hpp>

namespace glrenderer {

// The reference's vertex stage saturates colours with max(0, c) then min(., 1), where a NaN
// operand gives way to the second one: NaN stays NaN, then becomes 1. SSE's max and min do
// exactly that, four components at once.
inline __m128 saturate(__m128 c) { return _mm_min_ps(_mm_max_ps(_mm_setzero_ps(), c), _mm_set1_ps(1.0f)); }
inline glm::vec4 saturate(const glm::vec4& c) {
    glm::vec4 out;
    _mm_storeu_ps(&out.x, saturate(_mm_loadu_ps(&c.x)));
    return out;
}

// A colour the reference takes as a constant (not in the vertex format) is clamped with NaN
// becoming 0 instead.
inline glm::vec4 saturateConstant(const glm::vec4& c) {
    glm::vec4 out;
    _mm_storeu_ps(&out.x, _mm_min_ps(_mm_max_ps(_mm_loadu_ps(&c.x), _mm_setzero_ps()), _mm_set1_ps(1.0f)));
    return out;
}

}  // namespace glrenderer
