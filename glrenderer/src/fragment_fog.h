#pragma once
// Fog in the fragment stage, over a lane type L (fragment_stage.h), in the reference's
// arithmetic (Mesa's fog program: the factor from STATE_FOG_PARAMS_OPTIMIZED, saturated, then a
// LRP with the fog colour; llvmpipe evaluates it per fragment, nothing fused but gallivm's
// exp2 polynomial). docs/reference-rules.md, Fog, has the measurements.
#include "exp2_approximation.h"
#include "glrenderer/fog.h"
#include "lane_clamp.h"

namespace glrenderer {

// A draw's fog constants broadcast to the lanes.
template <class L>
struct FogLanes {
    typename L::Float linearScale, linearBias, expScale, color[3];

    explicit FogLanes(const FogState& fog)
        : linearScale(L::floats(fog.linearScale)),
          linearBias(L::floats(fog.linearBias)),
          expScale(L::floats(fog.expScale)),
          color{L::floats(fog.color[0]), L::floats(fog.color[1]), L::floats(fog.color[2])} {}

    // The fraction of the fragment's own colour that remains at fog coordinate `c`, in [0, 1].
    typename L::Float factor(FogMode mode, typename L::Float c) const {
        if (mode == FogMode::Linear) return clampUnit<L>(L::add(L::mul(c, linearScale), linearBias));
        typename L::Float t = L::mul(expScale, c);
        if (mode == FogMode::Exp2) t = L::mul(t, t);
        return clampUnit<L>(exp2Approximation<L>(L::sub(L::floats(0.0f), t)));
    }

    // Channel `i` of colour `c` fogged by factor f: f * c + (1 - f) * fog colour.
    typename L::Float apply(int i, typename L::Float f, typename L::Float c) const {
        return L::add(L::mul(f, c), L::mul(L::sub(L::floats(1.0f), f), color[i]));
    }
};

}  // namespace glrenderer
