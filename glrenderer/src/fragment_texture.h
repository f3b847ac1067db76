#pragma once
// Texturing in the fragment stage, over a lane type L (fragment_stage.h), in the reference's
// arithmetic: llvmpipe's 8-bit (AoS) sampler for RGBA8-like textures with REPEAT or
// CLAMP_TO_EDGE wraps (lp_bld_sample_aos.c), its float (SoA) sampler for a GL_CLAMP wrap
// (fragment_texture_float.h), its level of detail per 2 x 2 quad (lp_bld_sample.c), then Mesa's
// fixed-function texture environment in float.
// docs/reference-rules.md, Textures, has the measurements.
#include <cstdint>

#include "fragment_inputs.h"
#include "fragment_texture_float.h"
#include "glrenderer/texture.h"
#include "texel_lanes.h"
#include "triangle_setup.h"

namespace glrenderer {

// The four bytes of words a and b lerped with weights w (0-255, 256 being one), as gallivm's
// lerp of unorm8 values: a + ((w * (b - a) + 128) >> 8), the rounding of SSSE3's pmulhrsw.
template <class L>
[[gnu::always_inline]] inline typename L::Int lerpWords(typename L::Int w, typename L::Int a, typename L::Int b) {
    return L::lerpBytes(w, a, b);
}

// gallivm's fast log2 (lp_build_fast_log2): floor(log2 x) - 1 plus the mantissa in [1, 2),
// exact at powers of two and linear between them.
template <class L>
typename L::Float fastLog2(typename L::Float x) {
    const typename L::Int bits = L::bitsOf(x);
    const typename L::Int exponent = L::sub(channel<L, 23>(bits), L::ints(127 + 1));
    const typename L::Float mantissa = L::fromBits(L::bitOr(L::bitAnd(bits, L::ints(0x007FFFFF)), L::ints(0x3F800000)));
    return L::add(L::toFloat(exponent), mantissa);
}

template <class L>
class TextureLanes {
public:
    using Float = typename L::Float;
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    explicit TextureLanes(const FragmentInputs& in)
        : s_(in.texCoord[0]), t_(in.texCoord[1]), q_(in.texCoord[2]), invW_(in.invW), texture_(in.texture),
          envColor_{L::floats(in.textureEnvColor[0]), L::floats(in.textureEnvColor[1]), L::floats(in.textureEnvColor[2]),
                    L::floats(in.textureEnvColor[3])},
          floatSampler_(in.texture, in.textureBorderColor) {}

    // The texel colour of the fragments at (x, y) (w their interpolated w), each channel in
    // [0, 1], read for the lanes of `live`.
    [[gnu::always_inline]] inline void sample(const FragmentKey& key, Float x, Float y, Float w, Mask live,
                                              Float texel[4]) const {
        Float s, t;
        coordinates(x, y, w, s, t);
        if (samplesInFloat(key)) {
            // The level of detail of the lane's quad and of the other quad of its 4 x 2 block
            // (the reference's 8 lanes), when the filters differ.
            Float lod = L::floats(0.0f), otherLod = lod;
            if (key.mipFilter != MipmapFilter::None || key.minFilter != key.magFilter) {
                const Int qx = L::bitAnd(L::roundToInt(x), L::ints(~1)), qy = L::bitAnd(L::roundToInt(y), L::ints(~1));
                lod = quadLod(key, L::toFloat(qx), L::toFloat(qy));
                if (key.minFilter != key.magFilter) otherLod = quadLod(key, L::toFloat(L::bitXor(qx, L::ints(2))), L::toFloat(qy));
            }
            floatSampler_.sample(key, s, t, lod, otherLod, live, texel);
            return;
        }
        const Level zero = Level::of(*texture_, 0);
        Int word;
        if (key.mipFilter == MipmapFilter::None && key.minFilter == key.magFilter) {
            word = sampleLevel(key, key.minFilter, s, t, zero, live);
        } else {
            const Float lod = quadLod(key, L::toFloat(L::bitAnd(L::roundToInt(x), L::ints(~1))),
                                      L::toFloat(L::bitAnd(L::roundToInt(y), L::ints(~1))));
            word = minified(key, s, t, lod, live);
            if (key.minFilter != key.magFilter) {
                // Magnified where lod <= 0: the magnification filter on level 0.
                const Mask minifiedLanes = L::greaterThan(lod, L::floats(0.0f));
                word = L::select(minifiedLanes, word, sampleLevel(key, key.magFilter, s, t, zero, live));
            }
        }
        wordToFloats<L>(word, texel);
    }

    const Float* envColor() const { return envColor_; }

private:
    using Level = LevelLanes<L>;

    static Float planeAt(const AttributePlane& p, Float x, Float y) {
        return L::fma(L::floats(p.dady), y, L::fma(L::floats(p.dadx), x, L::floats(p.a0)));
    }
    // s/q and t/q at (x, y), as the reference's TXP: each times the reciprocal of q.
    void coordinates(Float x, Float y, Float w, Float& s, Float& t) const {
        const Float oneOverQ = L::div(L::floats(1.0f), L::mul(planeAt(q_, x, y), w));
        s = L::mul(L::mul(planeAt(s_, x, y), w), oneOverQ);
        t = L::mul(L::mul(planeAt(t_, x, y), w), oneOverQ);
    }
    void coordinates(Float x, Float y, Float& s, Float& t) const {
        coordinates(x, y, L::div(L::floats(1.0f), planeAt(invW_, x, y)), s, t);
    }

    // The level of detail of the 2 x 2 quads at (qx, qy) (even internal x and y): the
    // coordinates' differences from its top-left pixel to the next in x and in y, scaled by
    // level 0's size, rho the larger of the two squared lengths, lod = log2(rho) / 2
    // (lp_build_rho without its approximations, lp_build_fast_log2). A 1D texture takes s alone,
    // squared too (measured: the unsquared form of newer Mesa differs by up to 16).
    [[gnu::always_inline]] inline Float quadLod(const FragmentKey& key, Float qx, Float qy) const {
        Float s00, t00, s10, t10, s01, t01;
        coordinates(qx, qy, s00, t00);
        coordinates(L::add(qx, L::floats(1.0f)), qy, s10, t10);
        coordinates(qx, L::add(qy, L::floats(1.0f)), s01, t01);
        const Float width = L::floats(static_cast<float>(texture_->width[0]));
        const Float dsdx = L::mul(L::sub(s10, s00), width), dsdy = L::mul(L::sub(s01, s00), width);
        if (key.texture1D) return L::mul(fastLog2<L>(L::max(L::mul(dsdx, dsdx), L::mul(dsdy, dsdy))), L::floats(0.5f));
        const Float height = L::floats(static_cast<float>(texture_->height[0]));
        const Float dtdx = L::mul(L::sub(t10, t00), height), dtdy = L::mul(L::sub(t01, t00), height);
        const Float rhoX = L::add(L::mul(dsdx, dsdx), L::mul(dtdx, dtdx));
        const Float rhoY = L::add(L::mul(dsdy, dsdy), L::mul(dtdy, dtdy));
        return L::mul(fastLog2<L>(L::max(rhoX, rhoY)), L::floats(0.5f));
    }

    // The minification filter with the mipmap filter at `lod`.
    [[gnu::always_inline]] inline Int minified(const FragmentKey& key, Float s, Float t, Float lod, Mask live) const {
        const Int last = L::ints(texture_->levelCount - 1);
        if (key.mipFilter == MipmapFilter::None) return sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, 0), live);
        if (key.mipFilter == MipmapFilter::Nearest) {
            const Int index = L::minInt(L::maxInt(L::roundToInt(lod), L::ints(0)), last);
            return sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, index, live), live);
        }
        // Linear: floor and fraction of lod; the fraction in 8 bits, truncated, weighs the two levels.
        const Float floor = L::floor(lod);
        const Int first = L::roundToInt(floor);
        const Int index0 = L::minInt(L::maxInt(first, L::ints(0)), last);
        const Int index1 = L::minInt(L::maxInt(L::add(first, L::ints(1)), L::ints(0)), last);
        const Int weight = L::maxInt(L::truncateToInt(L::mul(L::sub(lod, floor), L::floats(256.0f))), L::ints(0));
        const Int word0 = sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, index0, live), live);
        const Int word1 = sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, index1, live), live);
        return lerpWords<L>(weight, word0, word1);
    }

    [[gnu::always_inline]] inline Int sampleLevel(const FragmentKey& key, TextureFilter filter, Float s, Float t, const Level& l, Mask live) const {
        if (filter == TextureFilter::Nearest) {
            const Int i = nearestIndex<L>(key.wrapS, s, l.width, texture_->powerOfTwoWidth);
            const Int j = nearestIndex<L>(key.wrapT, t, l.height, texture_->powerOfTwoHeight);
            return l.fetch(*texture_, i, j, live);
        }
        Int i0, i1, j0, j1, wi, wj;
        linear(key.wrapS, s, l.width, texture_->powerOfTwoWidth, i0, i1, wi);
        linear(key.wrapT, t, l.height, texture_->powerOfTwoHeight, j0, j1, wj);
        const Int top = lerpWords<L>(wi, l.fetch(*texture_, i0, j0, live), l.fetch(*texture_, i1, j0, live));
        const Int bottom = lerpWords<L>(wi, l.fetch(*texture_, i0, j1, live), l.fetch(*texture_, i1, j1, live));
        return lerpWords<L>(wj, top, bottom);
    }

    // The two texel indices and the weight (0-255) of coordinate c under LINEAR, in 8.8 fixed
    // point: round(c * size * 256) - 128.
    [[gnu::always_inline]] static inline void linear(TextureWrap wrap, Float c, Int size, bool pot, Int& i0, Int& i1,
                                                     Int& weight) {
        const Int last = L::sub(size, L::ints(1));
        if (wrap == TextureWrap::Repeat && !pot) {
            const Float f = L::sub(c, L::floor(c));
            const Int fixed = L::sub(L::roundToInt(L::mul(L::mul(f, L::toFloat(size)), L::floats(256.0f))), L::ints(128));
            weight = L::bitAnd(fixed, L::ints(0xFF));
            const Int i = L::template shiftRightSigned<8>(fixed);
            i0 = L::minInt(L::select(L::lessThan(i, L::ints(0)), last, i), last);  // -1 wraps to the last
            i1 = L::select(L::lessThan(i0, last), L::add(i0, L::ints(1)), L::ints(0));
            return;
        }
        const Float scaled = L::toFloat(L::template shiftLeft<8>(size));
        const Int fixed = L::sub(L::roundToInt(L::mul(c, scaled)), L::ints(128));
        weight = L::bitAnd(fixed, L::ints(0xFF));
        i0 = L::template shiftRightSigned<8>(fixed);
        i1 = L::add(i0, L::ints(1));
        if (wrap == TextureWrap::Repeat) {
            i0 = L::bitAnd(i0, last);
            i1 = L::bitAnd(i1, last);
        } else {
            i0 = L::minInt(L::maxInt(i0, L::ints(0)), last);
            i1 = L::minInt(L::maxInt(i1, L::ints(0)), last);
        }
    }

    AttributePlane s_, t_, q_, invW_;
    const Texture* texture_;
    Float envColor_[4];
    FloatTextureSampler<L> floatSampler_;
};

// The texture environment: the fragment's colour `c` (RGBA, in float) combined with the texel
// as Mesa's fixed-function fragment program combines them for the texture's base format.
template <class L>
[[gnu::always_inline]] inline void applyTextureEnv(const FragmentKey& key, const typename L::Float texel[4], const typename L::Float envColor[4],
                     typename L::Float c[4]) {
    using Float = typename L::Float;
    const TextureBase base = key.textureBase;
    const bool hasColor = base != TextureBase::Alpha;
    const bool hasAlpha = base == TextureBase::Alpha || base == TextureBase::LuminanceAlpha ||
                          base == TextureBase::Intensity || base == TextureBase::Rgba;
    // Mesa's LRP as NIR lowers it for llvmpipe (nir_lower_flrp's strict form, no fused multiply-add):
    // a * (1 - f) + b * f.
    auto mix = [](Float a, Float b, Float f) {
        return L::add(L::mul(a, L::sub(L::floats(1.0f), f)), L::mul(b, f));
    };
    switch (key.textureEnv) {
    case TextureEnv::Off: return;
    case TextureEnv::Modulate:
        if (hasColor) for (int i = 0; i < 3; ++i) c[i] = L::mul(c[i], texel[i]);
        if (hasAlpha) c[3] = L::mul(c[3], texel[3]);
        return;
    case TextureEnv::Replace:
        if (hasColor) for (int i = 0; i < 3; ++i) c[i] = texel[i];
        if (hasAlpha) c[3] = texel[3];
        return;
    case TextureEnv::Decal:
        if (base == TextureBase::Rgb) for (int i = 0; i < 3; ++i) c[i] = texel[i];
        if (base == TextureBase::Rgba) for (int i = 0; i < 3; ++i) c[i] = mix(c[i], texel[i], texel[3]);
        return;
    case TextureEnv::Blend:
        if (hasColor) for (int i = 0; i < 3; ++i) c[i] = mix(c[i], envColor[i], texel[i]);
        if (base == TextureBase::Intensity) c[3] = mix(c[3], envColor[3], texel[3]);
        else if (hasAlpha) c[3] = L::mul(c[3], texel[3]);
        return;
    case TextureEnv::Add:
        if (hasColor) for (int i = 0; i < 3; ++i) c[i] = L::add(c[i], texel[i]);
        if (base == TextureBase::Intensity) c[3] = L::add(c[3], texel[3]);
        else if (hasAlpha) c[3] = L::mul(c[3], texel[3]);
        return;
    }
}

}  // namespace glrenderer
