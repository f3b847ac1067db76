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
#include "plane_lanes.h"
#include "texel_lanes.h"
#include "triangle_setup.h"

namespace glrenderer {

// A texel's four bytes as two words of 16-bit fields, each 0-255: bytes 0 and 2 (red, blue)
// and bytes 1 and 3 (green, alpha). The bilinear and mipmap lerps work on them, as llvmpipe's
// 8-bit sampler does, with no repacking between lerps.
template <class L>
struct TexelFields {
    typename L::Int redBlue, greenAlpha;

    static TexelFields of(typename L::Int word) {
        const typename L::Int low = L::ints(0x00FF00FF);
        return {L::bitAnd(word, low), L::shiftRight16By8(word)};
    }
    // The texel words again.
    typename L::Int word() const { return L::bitOr(redBlue, L::template shiftLeft<8>(greenAlpha)); }
    // Field 0 (low) or 1 (high) of a word as a float channel.
    template <int Field>
    static typename L::Float channel(typename L::Int fields) {
        if constexpr (Field == 1)
            return unormToFloat<L>(L::template shiftRightUnsigned<16>(fields));
        else
            return unormToFloat<L>(L::bitAnd(fields, L::ints(0xFFFF)));
    }
};

// a and b lerped with weights w (0-255, 256 being one), as gallivm's lerp of unorm8 values:
// a + ((w * (b - a) + 128) >> 8), the rounding of SSSE3's pmulhrsw.
template <class L>
[[gnu::always_inline]] inline TexelFields<L> lerpTexels(typename L::Int w, const TexelFields<L>& a,
                                                        const TexelFields<L>& b) {
    return {L::lerpFields(w, a.redBlue, b.redBlue), L::lerpFields(w, a.greenAlpha, b.greenAlpha)};
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

// How a block's lanes lie on the 2 x 2 quads that share a level of detail (the reference's
// quads: from even internal x and y).
enum class QuadLanes {
    PerLane,   // anywhere: each lane evaluates its quad's corners
    RowPairs,  // one row from an even x: lanes 2k and 2k + 1 are one row of a quad
    TwoRows,   // from an even x and an even row: the first half of the lanes that row, the second half the next
};

template <class L>
class TextureLanes {
public:
    using Float = typename L::Float;
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    // Only a textured key's texture is read: an untextured primitive's record may still point at
    // the texture of the draw it last served, freed since. (`key` the routine's: a fast path's
    // constant, not read from the record.)
    [[gnu::always_inline]] TextureLanes(const FragmentKey& key, const FragmentInputs& in)
        : s_(in.texCoord[0]),
          t_(in.texCoord[1]),
          q_(in.texCoord[2]),
          invW_(in.invW()),
          texture_(key.textureEnv != TextureEnv::Off ? in.texture : nullptr),
          envColor_{L::floats(in.textureEnvColor[0]), L::floats(in.textureEnvColor[1]),
                    L::floats(in.textureEnvColor[2]), L::floats(in.textureEnvColor[3])},
          width0_(L::floats(texture_ ? static_cast<float>(texture_->width[0]) : 0.0f)),
          height0_(L::floats(texture_ ? static_cast<float>(texture_->height[0]) : 0.0f)),
          lastLevel_(L::ints(texture_ ? texture_->levelCount - 1 : 0)),
          floatSampler_(texture_, in.textureBorderColor) {}

    // The planes of `in` in the lanes `lanes` only (FragmentLanes::take).
    [[gnu::always_inline]] void take(const FragmentInputs& in, Mask lanes) {
        s_.take(in.texCoord[0], lanes), t_.take(in.texCoord[1], lanes), q_.take(in.texCoord[2], lanes);
        invW_.take(in.invW(), lanes);
    }

    // The texel colour of the fragments at (x, y) (w their interpolated w), each channel in
    // [0, 1], read for the lanes of `live`, lying on the quads as `Quads` says: with RowPairs or
    // TwoRows, lanes share the level of detail's coordinates.
    template <QuadLanes Quads>
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
                if (key.minFilter != key.magFilter)
                    otherLod = quadLod(key, L::toFloat(L::bitXor(qx, L::ints(2))), L::toFloat(qy));
            }
            floatSampler_.sample(key, s, t, lod, otherLod, live, texel);
            return;
        }
        const Level zero = Level::of(*texture_, 0);
        TexelFields<L> fields;
        if (!key.samplesLod()) {
            fields = sampleLevel(key, key.minFilter, s, t, zero, live);
        } else {
            Float lod;
            if constexpr (Quads == QuadLanes::TwoRows) {
                lod = twoRowQuadLod(key, s, t);
            } else if constexpr (Quads == QuadLanes::RowPairs) {
                lod = rowQuadLod(key, x, y, s, t);
            } else {
                lod = quadLod(key, L::toFloat(L::bitAnd(L::roundToInt(x), L::ints(~1))),
                              L::toFloat(L::bitAnd(L::roundToInt(y), L::ints(~1))));
            }
            fields = minified(key, s, t, lod, live);
            if (key.minFilter != key.magFilter) {
                // Magnified where lod <= 0: the magnification filter on level 0.
                const Mask minifiedLanes = L::greaterThan(lod, L::floats(0.0f));
                const TexelFields<L> magnified = sampleLevel(key, key.magFilter, s, t, zero, live);
                fields = {L::select(minifiedLanes, fields.redBlue, magnified.redBlue),
                          L::select(minifiedLanes, fields.greenAlpha, magnified.greenAlpha)};
            }
        }
        texel[0] = TexelFields<L>::template channel<0>(fields.redBlue);
        texel[1] = TexelFields<L>::template channel<0>(fields.greenAlpha);
        texel[2] = TexelFields<L>::template channel<1>(fields.redBlue);
        texel[3] = TexelFields<L>::template channel<1>(fields.greenAlpha);
    }

    // The texel word at (x, y) of level 0 under the key's wraps, nearest: a depth or stencil
    // image's value (TexelUse).
    [[gnu::always_inline]] inline Int word(const FragmentKey& key, Float x, Float y, Mask live) const {
        Float s, t;
        coordinates(x, y, s, t);
        return sampleLevel(key, TextureFilter::Nearest, s, t, Level::of(*texture_, 0), live).word();
    }

    const Float* envColor() const { return envColor_; }

private:
    using Level = LevelLanes<L>;

    // s/q and t/q at (x, y), as the reference's TXP: each times the reciprocal of q.
    void coordinates(Float x, Float y, Float w, Float& s, Float& t) const {
        const Float oneOverQ = L::div(L::floats(1.0f), L::mul(q_.at(x, y), w));
        s = L::mul(L::mul(s_.at(x, y), w), oneOverQ);
        t = L::mul(L::mul(t_.at(x, y), w), oneOverQ);
    }
    void coordinates(Float x, Float y, Float& s, Float& t) const {
        coordinates(x, y, L::div(L::floats(1.0f), invW_.at(x, y)), s, t);
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
        return lodOfDifferences(key, L::sub(s10, s00), L::sub(t10, t00), L::sub(s01, s00), L::sub(t01, t00));
    }

    // quadLod for lanes on consecutive pixels of one row from an even x: lanes 2k and 2k + 1 are
    // one row of a quad, whose coordinates (s, t) are the lanes' own; the quad's other row is
    // evaluated at the lanes' columns. The same coordinates at the same pixels, so the same bits:
    // the difference down the quad may come out negated (the lanes' row at its bottom), which
    // IEEE subtraction makes exact and the square undoes.
    [[gnu::always_inline]] inline Float rowQuadLod(const FragmentKey& key, Float x, Float y, Float s, Float t) const {
        const Int row = L::roundToInt(y);
        Float otherS, otherT;
        coordinates(x, L::toFloat(L::bitXor(row, L::ints(1))), otherS, otherT);
        const Mask onTop = L::lessThan(L::bitAnd(row, L::ints(1)), L::ints(1));
        const Float topS = L::select(onTop, s, otherS), topT = L::select(onTop, t, otherT);
        return lodOfDifferences(key, L::sub(L::duplicateOdd(topS), L::duplicateEven(topS)),
                                L::sub(L::duplicateOdd(topT), L::duplicateEven(topT)),
                                L::sub(L::duplicateEven(otherS), L::duplicateEven(s)),
                                L::sub(L::duplicateEven(otherT), L::duplicateEven(t)));
    }

    // quadLod for lanes on two rows of quads (QuadLanes::TwoRows): every coordinate it takes is a
    // lane's own. The difference down a quad comes out negated in the second row's lanes, which
    // IEEE subtraction makes exact and the square undoes.
    [[gnu::always_inline]] inline Float twoRowQuadLod(const FragmentKey& key, Float s, Float t) const {
        const Float leftS = L::duplicateEven(s), leftT = L::duplicateEven(t);
        return lodOfDifferences(key, L::firstHalfTwice(L::sub(L::duplicateOdd(s), leftS)),
                                L::firstHalfTwice(L::sub(L::duplicateOdd(t), leftT)),
                                L::sub(L::swapHalves(leftS), leftS), L::sub(L::swapHalves(leftT), leftT));
    }

    // The level of detail from a quad's coordinate differences across (x) and down (y).
    [[gnu::always_inline]] inline Float lodOfDifferences(const FragmentKey& key, Float sx, Float tx, Float sy,
                                                         Float ty) const {
        const Float dsdx = L::mul(sx, width0_), dsdy = L::mul(sy, width0_);
        if (key.texture1D) return L::mul(fastLog2<L>(L::max(L::mul(dsdx, dsdx), L::mul(dsdy, dsdy))), L::floats(0.5f));
        const Float dtdx = L::mul(tx, height0_), dtdy = L::mul(ty, height0_);
        const Float rhoX = L::add(L::mul(dsdx, dsdx), L::mul(dtdx, dtdx));
        const Float rhoY = L::add(L::mul(dsdy, dsdy), L::mul(dtdy, dtdy));
        return L::mul(fastLog2<L>(L::max(rhoX, rhoY)), L::floats(0.5f));
    }

    // The minification filter with the mipmap filter at `lod`.
    [[gnu::always_inline]] inline TexelFields<L> minified(const FragmentKey& key, Float s, Float t, Float lod,
                                                          Mask live) const {
        const Int last = lastLevel_;
        if (key.mipFilter == MipmapFilter::None)
            return sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, 0), live);
        if (key.mipFilter == MipmapFilter::Nearest) {
            const Int index = L::minInt(L::maxInt(L::roundToInt(lod), L::ints(0)), last);
            return sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, index), live);
        }
        // Linear: floor and fraction of lod; the fraction in 8 bits, truncated, weighs the two levels.
        const Float floor = L::floor(lod);
        const Int first = L::roundToInt(floor);
        const Int index0 = L::minInt(L::maxInt(first, L::ints(0)), last);
        const Int index1 = L::minInt(L::maxInt(L::add(first, L::ints(1)), L::ints(0)), last);
        const Int weight = L::maxInt(L::truncateToInt(L::mul(L::sub(lod, floor), L::floats(256.0f))), L::ints(0));
        const TexelFields<L> texel0 = sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, index0), live);
        const TexelFields<L> texel1 = sampleLevel(key, key.minFilter, s, t, Level::of(*texture_, index1), live);
        return lerpTexels<L>(weight, texel0, texel1);
    }

    [[gnu::always_inline]] inline TexelFields<L> sampleLevel(const FragmentKey& key, TextureFilter filter, Float s,
                                                             Float t, const Level& l, Mask live) const {
        if (filter == TextureFilter::Nearest) {
            const Int i = nearestIndex<L>(key.wrapS, s, l.width, texture_->powerOfTwoWidth);
            const Int j = nearestIndex<L>(key.wrapT, t, l.height, texture_->powerOfTwoHeight);
            return TexelFields<L>::of(l.fetch(*texture_, i, j, live));
        }
        Int i0, i1, j0, j1, wi, wj;
        linear(key.wrapS, s, l.width, texture_->powerOfTwoWidth, i0, i1, wi);
        linear(key.wrapT, t, l.height, texture_->powerOfTwoHeight, j0, j1, wj);
        const TexelFields<L> top = lerpTexels<L>(wi, fetch(l, i0, j0, live), fetch(l, i1, j0, live));
        const TexelFields<L> bottom = lerpTexels<L>(wi, fetch(l, i0, j1, live), fetch(l, i1, j1, live));
        return lerpTexels<L>(wj, top, bottom);
    }

    // The texel at column i, row j of level l. (Always inlined: as a lambda, GCC called it out
    // of line once the routines grew, 11% of the fog-textured terrain's CPU.)
    [[gnu::always_inline]] inline TexelFields<L> fetch(const Level& l, Int i, Int j, Mask live) const {
        return TexelFields<L>::of(l.fetch(*texture_, i, j, live));
    }

    // The two texel indices and the weight (0-255) of coordinate c under LINEAR, in 8.8 fixed
    // point: round(c * size * 256) - 128.
    [[gnu::always_inline]] static inline void linear(TextureWrap wrap, Float c, Int size, bool pot, Int& i0, Int& i1,
                                                     Int& weight) {
        const Int last = L::sub(size, L::ints(1));
        if (wrap == TextureWrap::Repeat && !pot) {
            const Float f = L::sub(c, L::floor(c));
            const Int fixed =
                L::sub(L::roundToInt(L::mul(L::mul(f, L::toFloat(size)), L::floats(256.0f))), L::ints(128));
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

    PlaneLanes<L> s_, t_, q_, invW_;
    const Texture* texture_;
    Float envColor_[4];
    Float width0_, height0_;  // level 0's size, for the level of detail
    Int lastLevel_;
    FloatTextureSampler<L> floatSampler_;
};

// The texture environment: the fragment's colour `c` (RGBA, in float) combined with the texel
// as Mesa's fixed-function fragment program combines them for the texture's base format, and
// with the colour sum the secondary colour `secondary` (else null) added to red, green and blue.
template <class L>
[[gnu::always_inline]] inline void applyTextureEnv(const FragmentKey& key, const typename L::Float texel[4],
                                                   const typename L::Float envColor[4],
                                                   const typename L::Float* secondary, typename L::Float c[4]) {
    using Float = typename L::Float;
    const TextureBase base = key.textureBase;
    const bool hasColor = base != TextureBase::Alpha;
    const bool hasAlpha = base == TextureBase::Alpha || base == TextureBase::LuminanceAlpha ||
                          base == TextureBase::Intensity || base == TextureBase::Rgba;
    // Mesa's LRP as NIR lowers it for llvmpipe (nir_lower_flrp's strict form, no fused multiply-add):
    // a * (1 - f) + b * f. A secondary colour `s` joins the second product first,
    // a * (1 - f) + (b * f + s), as the reference's compiled program orders the sum (measured).
    auto mix = [](Float a, Float b, Float f, const Float* s) {
        const Float second = s ? L::add(L::mul(b, f), *s) : L::mul(b, f);
        return L::add(L::mul(a, L::sub(L::floats(1.0f), f)), second);
    };
    const auto sum = [&](int i) { return secondary ? &secondary[i] : nullptr; };
    bool summed = false;  // the secondary colour is in
    switch (key.textureEnv) {
    case TextureEnv::Off: break;
    case TextureEnv::Modulate:
        if (hasColor)
            for (int i = 0; i < 3; ++i) c[i] = L::mul(c[i], texel[i]);
        if (hasAlpha) c[3] = L::mul(c[3], texel[3]);
        break;
    case TextureEnv::Replace:
        if (hasColor)
            for (int i = 0; i < 3; ++i) c[i] = texel[i];
        if (hasAlpha) c[3] = texel[3];
        break;
    case TextureEnv::Decal:
        if (base == TextureBase::Rgb)
            for (int i = 0; i < 3; ++i) c[i] = texel[i];
        if (base == TextureBase::Rgba) {
            for (int i = 0; i < 3; ++i) c[i] = mix(c[i], texel[i], texel[3], sum(i));
            summed = true;
        }
        break;
    case TextureEnv::Blend:
        if (hasColor) {
            for (int i = 0; i < 3; ++i) c[i] = mix(c[i], envColor[i], texel[i], sum(i));
            summed = true;
        }
        if (base == TextureBase::Intensity)
            c[3] = mix(c[3], envColor[3], texel[3], nullptr);
        else if (hasAlpha)
            c[3] = L::mul(c[3], texel[3]);
        break;
    case TextureEnv::Add:  // saturated, as Mesa's program saturates its ADD
        if (hasColor)
            for (int i = 0; i < 3; ++i) c[i] = clampUnit<L>(L::add(c[i], texel[i]));
        if (base == TextureBase::Intensity)
            c[3] = clampUnit<L>(L::add(c[3], texel[3]));
        else if (hasAlpha)
            c[3] = L::mul(c[3], texel[3]);
        break;
    }
    if (secondary && !summed) {
        for (int i = 0; i < 3; ++i) c[i] = L::add(c[i], secondary[i]);
    }
}

}  // namespace glrenderer
