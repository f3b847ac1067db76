#include "smooth_primitives.h"
#include "smooth_triangle.h"

namespace glrenderer {
namespace {

bool replacesColor(const DrawState& state) {
    return state.texture.env == TextureEnv::Replace && state.texture.use == TexelUse::Color;
}

// The reference multiplies the final alpha by the coverage.
glm::vec4 alphaCovered(const glm::vec4& c, float coverage) { return {c.r, c.g, c.b, c.a * coverage}; }

// Under GL_REPLACE the alpha the coverage multiplies is the texel's; the key's GL_MODULATE takes
// these colours to GL_REPLACE's colour and the reference's alpha: white and the coverage for a
// texture of colour and alpha, white and alpha * coverage for one without alpha, the fragment's
// own colour and the coverage for an alpha texture.
glm::vec4 texelCovered(const glm::vec4&, float coverage) { return {1.0f, 1.0f, 1.0f, coverage}; }
glm::vec4 opaqueTexelCovered(const glm::vec4& c, float coverage) { return {1.0f, 1.0f, 1.0f, c.a * coverage}; }
glm::vec4 alphaTexelCovered(const glm::vec4& c, float coverage) { return {c.r, c.g, c.b, coverage}; }

}  // namespace

FragmentKey smoothFragmentKey(const DrawState& state) {
    FragmentKey key = flatFragmentKey(state);
    if (replacesColor(state)) key.textureEnv = TextureEnv::Modulate;
    return key;
}

SmoothShading smoothShading(const DrawState& state) {
    const bool flat = state.shadeModel == ShadeModel::Flat;
    if (!replacesColor(state)) return {flat, alphaCovered};
    switch (state.texture.base) {
    case TextureBase::Alpha: return {flat, alphaTexelCovered};
    case TextureBase::Luminance:
    case TextureBase::Rgb: return {flat, opaqueTexelCovered};
    default: return {flat, texelCovered};
    }
}

}  // namespace glrenderer
