#pragma once
// Texturing in the fragment stage, over a lane type L (fragment_stage.h), in the reference's
// arithmetic: llvmpipe's 8-bit (AoS) sampler for RGBA8-like textures with REPEAT or
// CLAMP_TO_EDGE wraps (lp_bld_sample_aos.c), then Mesa's fixed-function texture environment in
// float. docs/reference-rules.md, Textures, has the measurements.
#include <cstdint>

#include "fragment_inputs.h"
#include "glrenderer/texture.h"
#include "triangle_setup.h"

namespace glrenderer {

// A texture channel as a float channel: the byte times 1/255 in float.
template <class L>
typename L::Float unormToFloat(typename L::Int byte) {
    return L::mul(L::toFloat(byte), L::floats(1.0f / 255.0f));
}

// gallivm's lerp of 8-bit values with an 8-bit weight w (prescaled: 256 is one): a plus
// (w * (b - a) + 128) >> 8, the rounding of SSSE3's pmulhrsw.
template <class L>
typename L::Int lerpUnorm8(typename L::Int w, typename L::Int a, typename L::Int b) {
    const typename L::Int product = L::mul(w, L::sub(b, a));
    return L::add(a, L::template shiftRightSigned<8>(L::add(product, L::ints(128))));
}

template <class L>
class TextureLanes {
public:
    using Float = typename L::Float;
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    explicit TextureLanes(const FragmentInputs& in)
        : s_(in.texCoord[0]), t_(in.texCoord[1]), q_(in.texCoord[2]), texels_(in.texture ? in.texture->texels.data() : nullptr),
          width_(in.texture ? in.texture->width : 1), height_(in.texture ? in.texture->height : 1),
          envColor_{L::floats(in.textureEnvColor[0]), L::floats(in.textureEnvColor[1]), L::floats(in.textureEnvColor[2]),
                    L::floats(in.textureEnvColor[3])} {}

    // The texel colour of the fragments at (x, y) (w their interpolated w), each channel in
    // [0, 1], read for the lanes of `live`.
    void sample(const FragmentKey& key, Float x, Float y, Float w, Mask live, Float texel[4]) const {
        // Projective coordinates (s/q, t/q), as the reference's TXP: times the reciprocal of q.
        const Float oneOverQ = L::div(L::floats(1.0f), L::mul(planeAt(q_, x, y), w));
        const Float s = L::mul(L::mul(planeAt(s_, x, y), w), oneOverQ);
        const Float t = L::mul(L::mul(planeAt(t_, x, y), w), oneOverQ);
        Int word;
        if (key.textureFilter == TextureFilter::Nearest) {
            const Int i = nearest(key.wrapS, s, width_), j = nearest(key.wrapT, t, height_);
            word = fetch(i, j, live);
        } else {
            Int i0, i1, j0, j1, wi, wj;
            linear(key.wrapS, s, width_, i0, i1, wi);
            linear(key.wrapT, t, height_, j0, j1, wj);
            const Int t00 = fetch(i0, j0, live), t01 = fetch(i1, j0, live);
            const Int t10 = fetch(i0, j1, live), t11 = fetch(i1, j1, live);
            word = L::ints(0);
            for (int c = 0; c < 4; ++c) {
                const int shift = 8 * c;
                const Int top = lerpUnorm8<L>(wi, channel(t00, shift), channel(t01, shift));
                const Int bottom = lerpUnorm8<L>(wi, channel(t10, shift), channel(t11, shift));
                word = L::bitOr(word, shiftLeftBy(lerpUnorm8<L>(wj, top, bottom), shift));
            }
        }
        for (int c = 0; c < 4; ++c) texel[c] = unormToFloat<L>(channel(word, 8 * c));
    }

    const Float* envColor() const { return envColor_; }

private:
    static Float planeAt(const AttributePlane& p, Float x, Float y) {
        return L::fma(L::floats(p.dady), y, L::fma(L::floats(p.dadx), x, L::floats(p.a0)));
    }
    static Int channel(Int word, int shift) {
        switch (shift) {
        case 0: return L::bitAnd(word, L::ints(0xFF));
        case 8: return L::bitAnd(L::template shiftRightUnsigned<8>(word), L::ints(0xFF));
        case 16: return L::bitAnd(L::template shiftRightUnsigned<16>(word), L::ints(0xFF));
        default: return L::template shiftRightUnsigned<24>(word);
        }
    }
    static Int shiftLeftBy(Int v, int shift) {
        switch (shift) {
        case 0: return v;
        case 8: return L::template shiftLeft<8>(v);
        case 16: return L::template shiftLeft<16>(v);
        default: return L::template shiftLeft<24>(v);
        }
    }
    static bool powerOfTwo(int n) { return (n & (n - 1)) == 0; }

    // The texel index of coordinate c under NEAREST: floor(c * size), wrapped.
    static Int nearest(TextureWrap wrap, Float c, int size) {
        if (wrap == TextureWrap::Repeat && !powerOfTwo(size)) {
            // fract, kept below one, times the size, truncated.
            const Float f = L::min(L::sub(c, L::floor(c)), L::floats(0x1.fffffep-1f));
            return L::roundToInt(L::floor(L::mul(f, L::floats(static_cast<float>(size)))));
        }
        const Int i = L::roundToInt(L::floor(L::mul(c, L::floats(static_cast<float>(size)))));
        if (wrap == TextureWrap::Repeat) return L::bitAnd(i, L::ints(size - 1));
        return L::minInt(L::maxInt(i, L::ints(0)), L::ints(size - 1));
    }

    // The two texel indices and the weight (0-255) of coordinate c under LINEAR, in 8.8 fixed
    // point: round(c * size * 256) - 128.
    static void linear(TextureWrap wrap, Float c, int size, Int& i0, Int& i1, Int& weight) {
        const Int last = L::ints(size - 1);
        if (wrap == TextureWrap::Repeat && !powerOfTwo(size)) {
            const Float f = L::sub(c, L::floor(c));
            const Int fixed = L::sub(L::roundToInt(L::mul(L::mul(f, L::floats(static_cast<float>(size))), L::floats(256.0f))),
                                     L::ints(128));
            weight = L::bitAnd(fixed, L::ints(0xFF));
            const Int i = L::template shiftRightSigned<8>(fixed);
            i0 = L::minInt(L::select(L::lessThan(i, L::ints(0)), last, i), last);  // -1 wraps to the last
            i1 = L::select(L::lessThan(i0, last), L::add(i0, L::ints(1)), L::ints(0));
            return;
        }
        const Int fixed = L::sub(L::roundToInt(L::mul(c, L::floats(static_cast<float>(size) * 256.0f))), L::ints(128));
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

    Int fetch(Int i, Int j, Mask live) const {
        return L::gather(texels_, L::add(L::mul(j, L::ints(width_)), i), live);
    }

    AttributePlane s_, t_, q_;
    const std::uint32_t* texels_;
    int width_, height_;
    Float envColor_[4];
};

// The texture environment: the fragment's colour `c` (RGBA, in float) combined with the texel
// as Mesa's fixed-function fragment program combines them for the texture's base format.
template <class L>
void applyTextureEnv(const FragmentKey& key, const typename L::Float texel[4], const typename L::Float envColor[4],
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
