#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

namespace glrenderer {

// GL's fog modes; Off when GL_FOG is disabled.
enum class FogMode : std::uint8_t { Off, Linear, Exp, Exp2 };

// Which computation gives a vertex its fog coordinate, the eye-space |z|: the reference's vertex
// program takes the eye position's z when lighting has computed the whole position (a
// positional light or a local viewer) and otherwise a dot product of its own, whose sums run
// in the opposite order (docs/reference-rules.md, Fog).
enum class FogDistance : std::uint8_t { OwnDotProduct, EyePosition };

// Fog as the fragment stage applies it, in the reference's constants (Mesa's
// STATE_FOG_PARAMS_OPTIMIZED): LINEAR is f = c * linearScale + linearBias, EXP and EXP2 are
// 2^-(c * expScale) and 2^-((c * expScale)^2), c the fragment's fog coordinate.
struct FogState {
    FogMode mode = FogMode::Off;
    FogDistance distance = FogDistance::OwnDotProduct;
    float linearScale = -1.0f, linearBias = 1.0f;
    float expScale = 0.0f;
    glm::vec4 color{0.0f};  // clamped to [0, 1]
    bool operator==(const FogState&) const = default;
};

// The state for GL's parameters, each constant computed as the reference computes it.
FogState makeFogState(FogMode mode, FogDistance distance, float density, float start, float end,
                      const glm::vec4& color);

}  // namespace glrenderer
