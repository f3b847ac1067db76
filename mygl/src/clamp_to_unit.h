#pragma once

namespace mygl {

// Clamps state values to [0, 1] as the reference's CLAMP does: NaN becomes 0.
template <class T>
constexpr T clampToUnit(T v) {
    return v > T(0) ? (v > T(1) ? T(1) : v) : T(0);
}

// The reference's vertex stage saturates colours with max then min, whose NaN operand loses
// to the second: NaN becomes 1.
template <class T>
constexpr T saturate(T v) {
    return v < T(1) ? (v > T(0) ? v : T(0)) : T(1);
}

}  // namespace mygl
