#include "image_texturing.h"

#include "fragment_stage.h"
#include "triangle_setup.h"

namespace glrenderer {

ImageTexturing::ImageTexturing(const DrawState& state, const glm::vec4& texCoord)
    : key_(withTexture(flatFragmentKey(state), state.texture)),
      fogMode_(state.fog.mode),
      fog_(state.fog),
      fogFactor_(fog_.factor(state.fog.mode, 0.0f)) {
    FragmentInputs in;
    WindowVertex constant;
    constant.texCoord = texCoord;
    in.setTexture(state.texture.texture.get(), state.texture.envColor, state.texture.borderColor, ConstantPlanes{},
                  constant);
    const TextureLanes<ScalarLanes> texture(key_, in);
    texture.sample<QuadLanes::PerLane>(key_, 0.0f, 0.0f, 1.0f, true, texel_);
    for (int i = 0; i < 4; ++i) envColor_[i] = state.texture.envColor[i];
}

std::uint32_t ImageTexturing::apply(std::uint32_t color) const {
    float c[4];
    for (int i = 0; i < 4; ++i) c[i] = unormToFloat<ScalarLanes>(color >> (8 * i) & 0xFF);
    applyTextureEnv<ScalarLanes>(key_, texel_, envColor_, nullptr, c);
    if (fogMode_ != FogMode::Off) {
        for (int i = 0; i < 3; ++i) c[i] = fog_.apply(i, fogFactor_, c[i]);
    }
    std::uint32_t out = 0;
    for (int i = 0; i < 4; ++i) out |= fragmentToUnorm8<ScalarLanes>(c[i]) << (8 * i);
    return out;
}

}  // namespace glrenderer
