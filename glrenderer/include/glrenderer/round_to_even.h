#pragma once
#include <cmath>
#include <cstdint>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace glrenderer {

// A float rounded to the nearest integer, ties to even (the default rounding mode, as
// std::nearbyint), in one instruction on x86-64: the conversion llvmpipe itself uses
// (cvtps_epi32). The value must fit in an int64; callers check their range first.
inline std::int64_t roundToEven(float value) {
#if defined(__x86_64__)
    return _mm_cvtss_si64(_mm_set_ss(value));
#else
    return static_cast<std::int64_t>(std::nearbyint(value));
#endif
}

}  // namespace glrenderer
