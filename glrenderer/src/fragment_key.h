#pragma once
#include <cstdint>

#include "glrenderer/draw_state.h"
#include "glrenderer/texture.h"

namespace glrenderer {

// How a primitive's colour reaches its fragments.
enum class Shading : std::uint8_t {
    Flat,         // one colour for the whole primitive
    Linear,       // colour planes, used as they are (1 / w is the constant 1, or screen-linear)
    Perspective,  // planes of colour / w, divided per fragment by the interpolated 1 / w
};

// What changes the work of the fragment stage, and nothing else: computed once per draw, it
// picks the routine that draws the draw's fragments (fragment_paths.h). Fields are in GL's
// order of the stage; a field that does not matter under the others is normalized (no depth
// function without the depth test), so that equal work has equal keys. A structural type: fast
// paths take their key as a template argument and the compiler removes every step it turns off.
struct FragmentKey {
    Shading shading = Shading::Flat;
    // Issue 16 adds here the texture environment and the texture's format.
    // Fog (issue 16): with a mode, the colour is fogged per fragment by a fog coordinate
    // interpolated with perspective, whatever the shading (FragmentInputs::fogCoord).
    FogMode fog = FogMode::Off;
    // Then the per-fragment tests: scissor, alpha test (function), stencil (functions, ops).
    bool depthTest = false;
    CompareFunc depthFunc = CompareFunc::Always;
    bool depthWrite = false;
    // Polygon offset of filled triangles (issue 16): a depth offset per primitive added to each
    // fragment's z (FragmentInputs::depthOffset), with the depth test only.
    bool depthOffset = false;
    // Then blending (equation, factors), the logic op and the colour and depth masks.

    // Texturing (issue 16), first in the stage's order but kept here, apart: the environment
    // (Off without a texture), what the texture's format holds, its filters and wraps. The
    // texture coordinates are interpolated with perspective, whatever the shading
    // (FragmentInputs::texCoord).
    TextureEnv textureEnv = TextureEnv::Off;
    bool texture1D = false;
    TextureBase textureBase = TextureBase::Rgba;
    TextureFilter minFilter = TextureFilter::Nearest, magFilter = TextureFilter::Nearest;
    MipmapFilter mipFilter = MipmapFilter::None;
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;

    bool operator==(const FragmentKey&) const = default;
};

// A key from its parts, normalized.
constexpr FragmentKey makeFragmentKey(Shading shading, bool depthTest, CompareFunc depthFunc, bool depthWrite) {
    if (!depthTest) return {shading, FogMode::Off, false, CompareFunc::Always, false, false};
    return {shading, FogMode::Off, true, depthFunc, depthWrite, false};
}

// `key` with fog of `mode`.
constexpr FragmentKey withFog(FragmentKey key, FogMode mode) {
    key.fog = mode;
    return key;
}

// `key` with texturing as `texture` makes it (none when its env is Off).
constexpr FragmentKey withTexture(FragmentKey key, TextureEnv env, bool oneDimensional, TextureBase base,
                                  TextureFilter minFilter, TextureFilter magFilter, MipmapFilter mipFilter,
                                  TextureWrap wrapS, TextureWrap wrapT) {
    key.textureEnv = env, key.texture1D = oneDimensional, key.textureBase = base;
    key.minFilter = minFilter, key.magFilter = magFilter, key.mipFilter = mipFilter;
    key.wrapS = wrapS, key.wrapT = wrapT;
    return key;
}
inline FragmentKey withTexture(FragmentKey key, const TextureState& t) {
    if (t.env == TextureEnv::Off) {
        const FragmentKey u;  // untextured
        return withTexture(key, u.textureEnv, u.texture1D, u.textureBase, u.minFilter, u.magFilter, u.mipFilter, u.wrapS,
                           u.wrapT);
    }
    return withTexture(key, t.env, t.oneDimensional, t.base, t.minFilter, t.magFilter, t.mipFilter, t.wrapS, t.wrapT);
}

// The key of a draw's state for primitives that interpolate their colour (triangles, lines).
inline FragmentKey fragmentKey(const DrawState& state) {
    const Shading shading = state.shadeModel == ShadeModel::Smooth ? Shading::Perspective : Shading::Flat;
    const FragmentKey key = makeFragmentKey(shading, state.depthTest, state.depthFunc, state.depthWrite);
    return withTexture(withFog(key, state.fog.mode), state.texture);
}

// The same key for primitives of one colour (points, bitmaps).
inline FragmentKey flatFragmentKey(const DrawState& state) {
    FragmentKey key = fragmentKey(state);
    key.shading = Shading::Flat;
    return key;
}

}  // namespace glrenderer
