#pragma once
#include "glrenderer/saturate.h"

namespace mygl {

// Clamps state values to [0, 1] as the reference's CLAMP does: NaN becomes 0.
template <class T>
constexpr T clampToUnit(T v) {
    return v > T(0) ? (v > T(1) ? T(1) : v) : T(0);
}

using glrenderer::saturate;

}  // namespace mygl
