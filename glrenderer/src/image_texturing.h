#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

#include "fragment_fog.h"
#include "fragment_key.h"
#include "glrenderer/draw_state.h"
#include "simd_scalar.h"

namespace glrenderer {

// What the reference's fragment program does to a glDrawPixels or glCopyPixels image's colours
// under texturing: the texture sampled at the current coordinates, read as a constant (no
// texture matrix, no generation; constant coordinates have no derivatives, so the magnification
// filter), combined with each colour by the environment, then fog at the image quad's fog
// coordinate, 0. Both are the same for every fragment of a colour, so each image colour is taken
// through them once, in the fragment stage's own arithmetic (sampler, environment, fog, colour
// conversion), and the quad then draws the results with neither.
class ImageTexturing {
public:
    // For a draw whose state has texturing on.
    ImageTexturing(const DrawState& state, const glm::vec4& texCoord);
    // A colour word (RGBA8, red in the low byte) as the fragment's colour after fog.
    std::uint32_t apply(std::uint32_t color) const;

private:
    FragmentKey key_;  // the environment's fields
    float texel_[4];
    float envColor_[4];
    FogMode fogMode_;
    FogLanes<ScalarLanes> fog_;
    float fogFactor_;  // with fog: the fraction of the colour kept
};

}  // namespace glrenderer
