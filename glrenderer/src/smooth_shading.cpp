#include "smooth_primitives.h"
#include "smooth_triangle.h"

namespace glrenderer {
namespace {

bool replacesColor(const DrawState& state) {
    return state.texture.env == TextureEnv::Replace && state.texture.use == TexelUse::Color;
}

}  // namespace

FragmentKey smoothFragmentKey(const DrawState& state) {
    FragmentKey key = flatFragmentKey(state);
    if (replacesColor(state)) key.textureEnv = TextureEnv::Modulate;
    return key;
}

SmoothShading smoothShading(const DrawState& state) {
    const TextureBase base = state.texture.base;
    const bool alpha = base == TextureBase::Alpha || base == TextureBase::LuminanceAlpha ||
                       base == TextureBase::Intensity || base == TextureBase::Rgba;
    return {state.shadeModel == ShadeModel::Flat, replacesColor(state), alpha, base != TextureBase::Alpha};
}

}  // namespace glrenderer
