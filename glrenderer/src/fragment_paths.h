#pragma once
#include <algorithm>
#include <array>
#include <span>
#include <string_view>

#include "fragment_inputs.h"
#include "fragment_key.h"

namespace glrenderer {

// A depth-tested key (GL_LESS, depth writes) of `shading` and `fog` whose colour a REPEAT texture
// of `base` modulates, filtered LINEAR with LINEAR mipmaps or else NEAREST without.
constexpr FragmentKey modulatedTexture(Shading shading, TextureBase base, bool mipmappedLinear,
                                       FogMode fog = FogMode::Off) {
    const TextureFilter filter = mipmappedLinear ? TextureFilter::Linear : TextureFilter::Nearest;
    return withTexture(withFog(makeFragmentKey(shading, true, CompareFunc::Less, true), fog), TextureEnv::Modulate,
                       false, base, filter, filter, mipmappedLinear ? MipmapFilter::Linear : MipmapFilter::None,
                       TextureWrap::Repeat, TextureWrap::Repeat);
}

// What scenes draw with nearly always (no depth test, or GL_LESS / GL_LEQUAL with depth writes, in
// each shading), smooth depth-tested LINEAR fog, the usual alpha blending and the common textures.
inline constexpr FragmentKey kCommonFragmentKeys[] = {
    makeFragmentKey(Shading::Flat, false, CompareFunc::Always, false),
    makeFragmentKey(Shading::Linear, false, CompareFunc::Always, false),
    makeFragmentKey(Shading::Perspective, false, CompareFunc::Always, false),
    makeFragmentKey(Shading::Flat, true, CompareFunc::Less, true),
    makeFragmentKey(Shading::Linear, true, CompareFunc::Less, true),
    makeFragmentKey(Shading::Perspective, true, CompareFunc::Less, true),
    makeFragmentKey(Shading::Flat, true, CompareFunc::LessEqual, true),
    makeFragmentKey(Shading::Linear, true, CompareFunc::LessEqual, true),
    makeFragmentKey(Shading::Perspective, true, CompareFunc::LessEqual, true),
    // A fogged landscape (bench-fog-terrain).
    withFog(makeFragmentKey(Shading::Perspective, true, CompareFunc::Less, true), FogMode::Linear),
    // Transparency over a depth-tested scene, without depth writes (bench-particles, the
    // blended_windows port): smooth, orthographic and flat (points).
    withBlend(makeFragmentKey(Shading::Perspective, true, CompareFunc::Less, false), BlendFactor::SrcAlpha,
              BlendFactor::OneMinusSrcAlpha),
    withBlend(makeFragmentKey(Shading::Linear, true, CompareFunc::Less, false), BlendFactor::SrcAlpha,
              BlendFactor::OneMinusSrcAlpha),
    withBlend(makeFragmentKey(Shading::Flat, true, CompareFunc::Less, false), BlendFactor::SrcAlpha,
              BlendFactor::OneMinusSrcAlpha),
    // Blending without the depth test (2D overlays).
    withBlend(makeFragmentKey(Shading::Perspective, false, CompareFunc::Always, false), BlendFactor::SrcAlpha,
              BlendFactor::OneMinusSrcAlpha),
    // Textured, depth-tested: RGB(A) bricks, LINEAR_MIPMAP_LINEAR, MODULATE (bench-textured-cubes),
    // and a NEAREST checkerboard; the same on orthographic primitives or in one colour (a flat key
    // that textures takes its linear key's routine: routineKey).
    modulatedTexture(Shading::Perspective, TextureBase::Rgb, true),
    modulatedTexture(Shading::Perspective, TextureBase::Rgba, true),
    modulatedTexture(Shading::Perspective, TextureBase::Rgba, false),
    modulatedTexture(Shading::Linear, TextureBase::Rgb, true),
    modulatedTexture(Shading::Linear, TextureBase::Rgba, true),
    modulatedTexture(Shading::Linear, TextureBase::Rgba, false),
    // A fogged landscape with a mipmapped ground texture (bench-fog-textured-terrain).
    modulatedTexture(Shading::Perspective, TextureBase::Rgb, true, FogMode::Linear),
    // glDrawPixels' quad without fragment operations (bench-draw-pixels; flat, by routineKey).
    withTexture(makeFragmentKey(Shading::Linear, false, CompareFunc::Always, false), TextureEnv::Replace, false,
                TextureBase::Rgba, TextureFilter::Nearest, TextureFilter::Nearest, MipmapFilter::None,
                TextureWrap::ClampToEdge, TextureWrap::ClampToEdge),
};

// The keys with fast paths of their own at every vector width: the common keys, then the alphaOne
// key of each that has one (withAlphaOne), so that a draw of alpha-one colours never loses its
// fast path. Each is compiled with its key as a constant, so that it holds only the steps the
// key turns on.
inline constexpr auto kFastFragmentKeys = [] {
    constexpr auto hasAlphaOneKey = [](const FragmentKey& key) { return withAlphaOne(key).alphaOne; };
    std::array<FragmentKey, std::size(kCommonFragmentKeys) + std::ranges::count_if(kCommonFragmentKeys, hasAlphaOneKey)>
        keys{};
    std::size_t next = 0;
    for (const FragmentKey& key : kCommonFragmentKeys) keys[next++] = key;
    for (const FragmentKey& key : kCommonFragmentKeys) {
        if (hasAlphaOneKey(key)) keys[next++] = withAlphaOne(key);
    }
    return keys;
}();

// The fragment routines of one vector width: a fast path per key of kFastFragmentKeys, and one
// routine that reads any key at run time (per block of lanes) for the others. The scalar
// width's routine for any key is the general path: it serves every key and is the reference
// the others are tested against, bit for bit (tests/unit/test_fragment_paths.cpp).
class FragmentPaths {
public:
    struct FastPath {
        FragmentKey key;
        FragmentRoutine routine;
    };
    using PathsOf = const FragmentPaths& (*)();

    // `lod`, if set, serves the keys that sample a texture with a level of detail.
    constexpr FragmentPaths(std::string_view name, std::span<const FastPath> fast, FragmentRoutine anyKey,
                            PathsOf lod = nullptr)
        : name_(name), fast_(fast), anyKey_(anyKey), lodPaths_(lod) {}

    std::string_view name() const { return name_; }
    // The fast path of `key` if it has one, else the routine for any key (of `lodPaths` for a
    // key with a level of detail).
    const FragmentRoutine& routine(FragmentKey key) const;
    std::span<const FastPath> fastPaths() const { return fast_; }
    const FragmentRoutine& anyKey() const { return anyKey_; }
    PathsOf lodPaths() const { return lodPaths_; }

private:
    std::string_view name_;
    std::span<const FastPath> fast_;
    FragmentRoutine anyKey_;
    PathsOf lodPaths_;
};

// One at a time, portable: the general path and scalar fast paths.
const FragmentPaths& scalarFragmentPaths();
// 8 lanes of AVX2 with FMA; only after cpuHasAvx2Fma().
const FragmentPaths& avx2FragmentPaths();
// The AVX2 paths compiled for AVX-512VL (32 registers); only after cpuHasAvx512().
const FragmentPaths& avx2EvexFragmentPaths();  // fast paths for keys with a level of detail only
// 16 lanes of AVX-512F; only after cpuHasAvx512(). Keys that sample a texture with a level of
// detail take the 8-lane avx2EvexFragmentPaths: with 14 gathers a block, 16-lane blocks on
// short spans made bench-textured-cubes take 1.3-1.9 times as long (AMD EPYC, 150 frames,
// alternating runs).
const FragmentPaths& avx512FragmentPaths();
// The widest this CPU runs (widestLanes()).
const FragmentPaths& bestFragmentPaths();
// The general path: the scalar routine for any key.
inline const FragmentRoutine& generalFragmentRoutine() { return scalarFragmentPaths().anyKey(); }

// The key whose routine draws a key's primitives: a flat key that reads its colour planes anyway
// (fog, texturing, the colour sum: constant planes, FragmentInputs::setFlatColor) does the work
// of its linear key, bit for bit.
constexpr FragmentKey routineKey(FragmentKey key) {
    if (key.shading == Shading::Flat && (key.fog != FogMode::Off || key.texturesColor() || key.colorSum)) {
        key.shading = Shading::Linear;
    }
    return key;
}

// A draw's fragment paths, chosen once per draw from its key (the routine of its routineKey). A
// primitive whose 1 / w is the constant 1 (w = 1 at every vertex, as in orthographic scenes)
// takes `constantW`: the key with linear shading, as dividing by one would change no bit.
struct FragmentChoice {
    // With the draw's state when the key reads its constants (fog, polygon offset).
    FragmentChoice(const FragmentPaths& paths, FragmentKey key);
    FragmentChoice(const FragmentPaths& paths, FragmentKey key, const DrawState& state);

    // The path of a primitive of perspective shading with this plane of 1 / w. The plane
    // (1, 0, 0) is 1 at every pixel, and x * 1 is x for every float x.
    const FragmentPath& path(const AttributePlane& invW) const {
        const bool constantOne = invW.a0 == 1.0f && invW.dadx == 0.0f && invW.dady == 0.0f;
        return constantOne ? constantW : varyingW;
    }

    FragmentPath varyingW, constantW;
    FogState fog;                 // the draw's, for the primitives' inputs when the key has fog
    PolygonOffset polygonOffset;  // the draw's, for filled triangles' depth offset
    FragmentOpsConstants ops;     // the draw's (issue 16), for every primitive's inputs
    const PolygonStipplePattern* polygonStipple = nullptr;  // the draw's, for filled triangles
    ScissorBox scissor;                                     // the draw's, for the bounds of lines (drawableRect)
    // The draw's texture (kept alive by the batch drawer until its triangles are drawn) and
    // environment and border colours, when the key has texturing.
    const Texture* texture = nullptr;
    glm::vec4 textureEnvColor{0.0f}, textureBorderColor{0.0f};
};

}  // namespace glrenderer
