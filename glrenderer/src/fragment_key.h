#pragma once
#include <cstdint>

#include "glrenderer/draw_state.h"
#include "glrenderer/texture.h"

namespace glrenderer {

// A pass of deferred shading (TileRasterizer): where a tile's opaque, depth-tested primitives
// overlap many times over, it draws them twice, first their depths alone, then the colour of
// each pixel's last winner only, instead of the colour of every fragment that passes for a while.
enum class DeferredPass : std::uint8_t {
    None,        // depth and colour at once
    Visibility,  // the depth test and depth writes alone; the depths written carry kDeferredMark
    Shade,       // the colour of the first fragment whose depth is a pixel's marked depth, unmarking it
};

// Set on a depth written by a visibility pass: 24-bit depths never have it, so the stored
// values of the primitives before the pass are told from those of the pass.
inline constexpr std::uint32_t kDeferredMark = 1u << 24;

// How a primitive's colour reaches its fragments.
enum class Shading : std::uint8_t {
    Flat,         // one colour for the whole primitive
    Linear,       // colour planes, used as they are (1 / w is the constant 1, or screen-linear)
    Perspective,  // planes of colour / w, divided per fragment by the interpolated 1 / w
};

// What changes the work of the fragment stage, and nothing else: computed once per draw, it
// picks the routine that draws the draw's fragments (fragment_paths.h). Fields are in GL's
// order of the stage (the per-fragment operations' group aside); a field that does not matter under the others is
// normalized (no depth function without the depth test), so that equal work has equal keys. A structural type: fast
// paths take their key as a template argument and the compiler removes every step it turns off.
struct FragmentKey {
    Shading shading = Shading::Flat;
    // Fog (issue 16): with a mode, the colour is fogged per fragment by a fog coordinate
    // interpolated with perspective, whatever the shading (FragmentInputs::fogCoord).
    FogMode fog = FogMode::Off;
    bool depthTest = false;
    CompareFunc depthFunc = CompareFunc::Always;
    bool depthWrite = false;
    // Polygon offset of filled triangles (issue 16): a depth offset per primitive added to each
    // fragment's z (FragmentInputs::depthOffset), with the depth test only.
    bool depthOffset = false;
    // Polygon stipple of filled triangles (issue 16): lanes off the pattern
    // (FragmentInputs::polygonStipple) are dropped before every test.
    bool polygonStipple = false;
    // Per-fragment operations (issue 16), each at its default when off; their constants are in
    // FragmentInputs::ops. Kept together here; the stage runs the alpha and stencil tests before
    // the depth test, as GL orders them. The scissor is no step: it cuts the primitives' bounds.
    CompareFunc alphaFunc = CompareFunc::Always;  // the alpha test
    bool stencilTest = false;
    CompareFunc stencilFunc = CompareFunc::Always;
    StencilOp stencilFail = StencilOp::Keep, stencilDepthFail = StencilOp::Keep, stencilDepthPass = StencilOp::Keep;
    BlendFactor blendSrc = BlendFactor::One, blendDst = BlendFactor::Zero;
    LogicOp logicOp = LogicOp::Copy;
    bool colorMask = false;  // some bits of the colour word are kept

    // Whether the stage reads the stored colour.
    constexpr bool readsColor() const {
        return blendSrc != BlendFactor::One || blendDst != BlendFactor::Zero || logicOp != LogicOp::Copy || colorMask;
    }

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
    // Separate specular colour (GL 1.2), after the texture environment and before fog: the
    // secondary colour (FragmentInputs::secondaryColor, shaded as the colour is) added to the
    // colour's red, green and blue.
    bool colorSum = false;

    // Texels as depths or stencil values (glDrawPixels and glCopyPixels of depth and stencil):
    // they replace the fragment's depth or the stencil reference, the colour stays flat.
    TexelUse texelUse = TexelUse::Color;

    DeferredPass deferredPass = DeferredPass::None;

    // Every vertex colour of the draw has alpha 1 (glColor3, an opaque material) and the alpha
    // goes to the colour word untouched (withAlphaOne): the fragments' alpha byte is 255, what
    // interpolating the ones and converting them gives, so alpha is not interpolated.
    bool alphaOne = false;

    // Whether the texture environment colours the fragments.
    constexpr bool texturesColor() const { return textureEnv != TextureEnv::Off && texelUse == TexelUse::Color; }

    // Whether texturing needs a level of detail: mipmaps, or two filters to choose between.
    [[gnu::always_inline]] constexpr bool samplesLod() const {
        return textureEnv != TextureEnv::Off && (mipFilter != MipmapFilter::None || minFilter != magFilter);
    }

    // Whether deferred shading draws this key's primitives exactly: each pixel's colour is that
    // of the last fragment to pass there (depth writes, the colour replaced: nothing read back,
    // no test on the colour, no stencil), and under GL_LESS that is the first fragment to reach
    // the pixel's final depth (the stored depth only decreases), found again from depths alone.
    // Only for keys whose colour costs (texturing): for the others the second pass costs more
    // than it saves.
    constexpr bool defersColor() const {
        return deferredPass == DeferredPass::None && depthTest && depthFunc == CompareFunc::Less && depthWrite &&
               !readsColor() && alphaFunc == CompareFunc::Always && !stencilTest && texturesColor();
    }

    bool operator==(const FragmentKey&) const = default;
};

// The two passes of deferred shading of a key that defersColor(): the visibility pass keeps only
// what decides which fragments pass, normalized so that keys share it.
constexpr FragmentKey visibilityKey(const FragmentKey& key) {
    FragmentKey visibility;
    visibility.depthTest = true, visibility.depthFunc = CompareFunc::Less, visibility.depthWrite = true;
    visibility.depthOffset = key.depthOffset, visibility.polygonStipple = key.polygonStipple;
    visibility.deferredPass = DeferredPass::Visibility;
    return visibility;
}
constexpr FragmentKey shadeKey(FragmentKey key) {
    key.deferredPass = DeferredPass::Shade;
    return key;
}

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

// `key` blending with factors `src` and `dst`.
constexpr FragmentKey withBlend(FragmentKey key, BlendFactor src, BlendFactor dst) {
    key.blendSrc = src, key.blendDst = dst;
    return key;
}

// `key` with the per-fragment operations of `ops`, normalized: a test that passes everything
// and changes nothing is off, blending is off under a logic op (GL), the depth-fail operation
// is Keep without the depth test.
constexpr FragmentKey withFragmentOps(FragmentKey key, const FragmentOps& ops) {
    if (ops.alphaTest) key.alphaFunc = ops.alphaFunc;
    const StencilState& s = ops.stencil;
    const bool writes = s.writeMask != 0;
    key.stencilFail = writes ? s.fail : StencilOp::Keep;
    key.stencilDepthFail = writes && key.depthTest ? s.depthFail : StencilOp::Keep;
    key.stencilDepthPass = writes ? s.depthPass : StencilOp::Keep;
    key.stencilFunc = s.func;
    key.stencilTest = s.enabled && (s.func != CompareFunc::Always || key.stencilFail != StencilOp::Keep ||
                                    key.stencilDepthFail != StencilOp::Keep || key.stencilDepthPass != StencilOp::Keep);
    if (!key.stencilTest) {
        key.stencilFunc = CompareFunc::Always;
        key.stencilFail = key.stencilDepthFail = key.stencilDepthPass = StencilOp::Keep;
    }
    if (ops.logicOpEnabled) key.logicOp = ops.logicOp;
    if (ops.blend && !ops.logicOpEnabled) key.blendSrc = ops.blendSrc, key.blendDst = ops.blendDst;
    key.colorMask = ops.colorMask != 0xFFFFFFFFu;
    return key;
}

// `key` with texturing as `texture` makes it (none when its env is Off).
constexpr FragmentKey withTexture(FragmentKey key, TextureEnv env, bool oneDimensional, TextureBase base,
                                  TextureFilter minFilter, TextureFilter magFilter, MipmapFilter mipFilter,
                                  TextureWrap wrapS, TextureWrap wrapT, TexelUse use = TexelUse::Color) {
    key.textureEnv = env, key.texture1D = oneDimensional, key.textureBase = base, key.texelUse = use;
    key.minFilter = minFilter, key.magFilter = magFilter, key.mipFilter = mipFilter;
    key.wrapS = wrapS, key.wrapT = wrapT;
    return key;
}
inline FragmentKey withTexture(FragmentKey key, const TextureState& t) {
    if (t.env == TextureEnv::Off) {
        const FragmentKey u;  // untextured
        return withTexture(key, u.textureEnv, u.texture1D, u.textureBase, u.minFilter, u.magFilter, u.mipFilter,
                           u.wrapS, u.wrapT);
    }
    return withTexture(key, t.env, t.oneDimensional, t.base, t.minFilter, t.magFilter, t.mipFilter, t.wrapS, t.wrapT,
                       t.use);
}

// `key` for a draw whose vertex colours all have alpha 1: alphaOne where the alpha would only be
// interpolated and stored, under smooth shading (a flat colour is one word already) and with
// nothing that reads it: no texturing, alpha test, blending, logic op or colour mask.
constexpr FragmentKey withAlphaOne(FragmentKey key) {
    key.alphaOne = key.shading != Shading::Flat && !key.texturesColor() && key.alphaFunc == CompareFunc::Always &&
                   !key.readsColor();
    return key;
}

// The key of a draw's state for primitives that interpolate their colour (triangles, lines).
inline FragmentKey fragmentKey(const DrawState& state) {
    const Shading shading = state.shadeModel == ShadeModel::Smooth ? Shading::Perspective : Shading::Flat;
    FragmentKey key =
        withFog(makeFragmentKey(shading, state.depthTest, state.depthFunc, state.depthWrite), state.fog.mode);
    key.colorSum = state.secondaryColors;
    return withTexture(withFragmentOps(key, state.fragmentOps), state.texture);
}

// The same key for primitives of one colour (points, bitmaps).
inline FragmentKey flatFragmentKey(const DrawState& state) {
    FragmentKey key = fragmentKey(state);
    key.shading = Shading::Flat;
    return key;
}

}  // namespace glrenderer
