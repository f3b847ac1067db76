#include "image_texturing.h"

#include "fragment_stage.h"
#include "simd_scalar.h"
#include "triangle_setup.h"

namespace glrenderer {

ImageTexturing::ImageTexturing(const DrawState& state, const glm::vec4& texCoord)
    : env_(state.texture.env),
      base_(state.texture.base),
      fogged_(state.fog.mode != FogMode::Off),
      fogFactor_(FogLanes<ScalarLanes>(state.fog).factor(state.fog.mode, 0.0f)),
      fogColor_(state.fog.color) {
    FragmentInputs in;
    in.key = withTexture(flatFragmentKey(state), state.texture);
    WindowVertex constant;
    constant.texCoord = texCoord;
    in.setTexture(state.texture.texture.get(), state.texture.envColor, state.texture.borderColor, ConstantPlanes{},
                  constant);
    const TextureLanes<ScalarLanes> texture(in);
    texture.sample<QuadLanes::PerLane>(in.key, 0.0f, 0.0f, 1.0f, true, texel_);
    for (int i = 0; i < 4; ++i) envColor_[i] = state.texture.envColor[i];
}

std::uint32_t ImageTexturing::apply(std::uint32_t color) const {
    FragmentKey key;
    key.textureEnv = env_;
    key.textureBase = base_;
    float c[4];
    for (int i = 0; i < 4; ++i) c[i] = unormToFloat<ScalarLanes>(color >> (8 * i) & 0xFF);
    applyTextureEnv<ScalarLanes>(key, texel_, envColor_, nullptr, c);
    if (fogged_) {
        FogState fog;
        fog.color = fogColor_;
        const FogLanes<ScalarLanes> lanes(fog);
        for (int i = 0; i < 3; ++i) c[i] = lanes.apply(i, fogFactor_, c[i]);
    }
    std::uint32_t out = 0;
    for (int i = 0; i < 4; ++i) out |= fragmentToUnorm8<ScalarLanes>(c[i]) << (8 * i);
    return out;
}

}  // namespace glrenderer
