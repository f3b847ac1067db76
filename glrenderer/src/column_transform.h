#pragma once
#include <xmmintrin.h>

#include <glm/vec4.hpp>

#include "glrenderer/matrix.h"

namespace glrenderer {

// transform() (matrix.h) on the four rows at once: a column times a coordinate, summed left to
// right, each product and sum rounded, as there.
class ColumnTransform {
public:
    explicit ColumnTransform(const Matrix& m)
        : c0_(_mm_loadu_ps(&m[0])), c1_(_mm_loadu_ps(&m[4])), c2_(_mm_loadu_ps(&m[8])), c3_(_mm_loadu_ps(&m[12])) {}

    __m128 apply(const glm::vec4& v) const {
        __m128 r = _mm_add_ps(_mm_mul_ps(c0_, _mm_set1_ps(v.x)), _mm_mul_ps(c1_, _mm_set1_ps(v.y)));
        r = _mm_add_ps(r, _mm_mul_ps(c2_, _mm_set1_ps(v.z)));
        return _mm_add_ps(r, _mm_mul_ps(c3_, _mm_set1_ps(v.w)));
    }

private:
    __m128 c0_, c1_, c2_, c3_;
};

}  // namespace glrenderer
