#pragma once

namespace glrenderer {

// Lanes of L (simd_*.h) clamped to [0, 1], NaN and negatives to 0, as the reference saturates.
template <class L>
typename L::Float clampUnit(typename L::Float v) {
    return L::min(L::max(v, L::floats(0.0f)), L::floats(1.0f));
}

}  // namespace glrenderer
