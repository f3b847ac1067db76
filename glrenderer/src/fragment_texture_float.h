#pragma once
// llvmpipe's float (SoA) sampler (lp_bld_sample_soa.c), which serves a texture with a GL_CLAMP
// wrap under a LINEAR filter (its 8-bit sampler takes REPEAT and CLAMP_TO_EDGE only): texels
// as floats, weights as float fractions, lerps as LLVM's fmuladd, the border colour for texels
// beyond a GL_CLAMP edge. docs/reference-rules.md, Textures, has the measurements.
#include <glm/vec4.hpp>

#include "fragment_key.h"
#include "texel_lanes.h"

namespace glrenderer {

// Whether the key's texture goes through the float sampler (a 1D texture's T wrap is Repeat).
[[gnu::always_inline]] constexpr bool samplesInFloat(const FragmentKey& key) {
    return key.wrapS == TextureWrap::Clamp || key.wrapT == TextureWrap::Clamp;
}

template <class L>
class FloatTextureSampler {
public:
    using Float = typename L::Float;
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    [[gnu::always_inline]] FloatTextureSampler(const Texture* texture, const glm::vec4& border)
        : texture_(texture),
          border_{L::floats(border[0]), L::floats(border[1]), L::floats(border[2]), L::floats(border[3])} {}

    // The texel colour at (s, t), `lod` the level of detail of the lane's quad and `otherLod`
    // that of the other quad of its block (the reference's 8 lanes hold two quads and choose
    // the filters' path for both: lp_build_sample_general).
    void sample(const FragmentKey& key, Float s, Float t, Float lod, Float otherLod, Mask live, Float out[4]) const {
        if (key.minFilter == key.magFilter)
            return mipmap(key, key.minFilter, key.mipFilter, s, t, lod, none(), live, out);
        // Linear where the lod says the linear filter; a block with any such lane samples every
        // lane linearly, the others' weights rounded to 0 or 1 (nearest, but a coordinate at
        // the texel's edge takes the lower texel, a GL_CLAMP coordinate <= 0 the border).
        const bool minLinear = key.minFilter == TextureFilter::Linear;
        const Mask linear = linearAt(minLinear, lod), otherLinear = linearAt(minLinear, otherLod);
        Float both[4], nearest[4];
        mipmap(key, TextureFilter::Linear, key.mipFilter, s, t, lod, L::butNot(live, linear), live, both);
        mipmap(key, TextureFilter::Nearest, minLinear ? MipmapFilter::None : key.mipFilter, s, t, lod, none(), live,
               nearest);
        const Mask blockLinear = L::either(linear, otherLinear);
        for (int c = 0; c < 4; ++c) out[c] = L::select(blockLinear, both[c], nearest[c]);
    }

private:
    using Level = LevelLanes<L>;

    static Mask none() { return L::lessThan(L::floats(1.0f), L::floats(0.0f)); }
    // Where the linear filter applies: minified (lod > 0) for a linear minification filter,
    // else magnified (not lod > 0).
    static Mask linearAt(bool minLinear, Float lod) {
        const Mask minified = L::greaterThan(lod, L::floats(0.0f));
        return minLinear ? minified : L::butNot(L::lessThan(L::floats(0.0f), L::floats(1.0f)), minified);
    }

    // LLVM's fmuladd lerp (lp_build_lerp on floats): v0 + x * (v1 - v0), fused on FMA CPUs.
    static Float lerp(Float x, Float v0, Float v1) { return L::multiplyAdd(x, L::sub(v1, v0), v0); }

    // The filter on the level(s) the mipmap filter picks at `lod` (lp_build_sample_mipmap):
    // NEAREST rounds lod, LINEAR lerps floor(lod) and the next level by lod's fraction, zero
    // where either level is clamped to the first or last.
    void mipmap(const FragmentKey& key, TextureFilter filter, MipmapFilter mip, Float s, Float t, Float lod,
                Mask nearestLanes, Mask live, Float out[4]) const {
        if (mip == MipmapFilter::None)
            return image(key, filter, s, t, Level::of(*texture_, 0), nearestLanes, live, out);
        const Int last = L::ints(texture_->levelCount - 1);
        if (mip == MipmapFilter::Nearest) {
            const Int index = L::minInt(L::maxInt(L::roundToInt(lod), L::ints(0)), last);
            return image(key, filter, s, t, Level::of(*texture_, index), nearestLanes, live, out);
        }
        const Float floor = L::floor(lod);
        const Int first = L::roundToInt(floor);
        const Mask clamped = L::either(L::lessThan(first, L::ints(0)), L::lessThan(L::sub(last, L::ints(1)), first));
        const Float weight = L::select(clamped, L::floats(0.0f), L::sub(lod, floor));
        const Int index0 = L::minInt(L::maxInt(first, L::ints(0)), last);
        const Int index1 = L::minInt(L::maxInt(L::add(first, L::ints(1)), L::ints(0)), last);
        Float next[4];
        image(key, filter, s, t, Level::of(*texture_, index0), nearestLanes, live, out);
        image(key, filter, s, t, Level::of(*texture_, index1), nearestLanes, live, next);
        for (int c = 0; c < 4; ++c) out[c] = lerp(weight, out[c], next[c]);
    }

    // One level under `filter`; LINEAR rounds the weights of `nearestLanes` to 0 or 1.
    void image(const FragmentKey& key, TextureFilter filter, Float s, Float t, const Level& l, Mask nearestLanes,
               Mask live, Float out[4]) const {
        const bool oneD = key.texture1D;
        if (filter == TextureFilter::Nearest) {
            const Int i = nearestIndex<L>(key.wrapS, s, l.width, texture_->powerOfTwoWidth);
            const Int j = oneD ? L::ints(0) : nearestIndex<L>(key.wrapT, t, l.height, texture_->powerOfTwoHeight);
            return wordToFloats<L>(l.fetch(*texture_, i, j, live), out);
        }
        Int i0, i1, j0 = L::ints(0), j1 = j0;
        Float ws, wt = L::floats(0.0f);
        linear(key.wrapS, s, l.width, texture_->powerOfTwoWidth, nearestLanes, i0, i1, ws);
        if (!oneD) linear(key.wrapT, t, l.height, texture_->powerOfTwoHeight, nearestLanes, j0, j1, wt);
        Float c00[4], c01[4], c10[4], c11[4];
        fetch(key, l, i0, j0, live, c00);
        fetch(key, l, i1, j0, live, c01);
        if (oneD) {
            for (int c = 0; c < 4; ++c) out[c] = lerp(ws, c00[c], c01[c]);
            return;
        }
        fetch(key, l, i0, j1, live, c10);
        fetch(key, l, i1, j1, live, c11);
        for (int c = 0; c < 4; ++c) out[c] = lerp(wt, lerp(ws, c00[c], c01[c]), lerp(ws, c10[c], c11[c]));
    }

    // The texels at (i, j) as floats; beyond a GL_CLAMP edge the border colour.
    void fetch(const FragmentKey& key, const Level& l, Int i, Int j, Mask live, Float out[4]) const {
        Mask outside = none();
        if (key.wrapS == TextureWrap::Clamp) outside = L::either(outside, beyond(i, l.width));
        if (key.wrapT == TextureWrap::Clamp) outside = L::either(outside, beyond(j, l.height));
        const Int zero = L::ints(0);
        wordToFloats<L>(l.fetch(*texture_, L::select(outside, zero, i), L::select(outside, zero, j), live), out);
        for (int c = 0; c < 4; ++c) out[c] = L::select(outside, border_[c], out[c]);
    }
    static Mask beyond(Int i, Int size) {
        return L::either(L::lessThan(i, L::ints(0)), L::lessThan(L::sub(size, L::ints(1)), i));
    }

    // The two texel indices and the weight of coordinate c under LINEAR (lp_build_sample_wrap_linear):
    // u = c * size - 1/2, i0 = floor(u), weight = u - i0, each wrap its way; GL_CLAMP clamps
    // c * size to [0, size] first and leaves the indices beyond the edges to the border.
    static void linear(TextureWrap wrap, Float c, Int size, bool pot, Mask nearestLanes, Int& i0, Int& i1,
                       Float& weight) {
        const Float sizeF = L::toFloat(size), half = L::floats(0.5f);
        const Int last = L::sub(size, L::ints(1));
        Float u;
        if (wrap == TextureWrap::Repeat && !pot)
            u = L::sub(L::mul(L::sub(c, L::floor(c)), sizeF), half);
        else if (wrap == TextureWrap::Repeat)
            u = L::sub(L::mul(c, sizeF), half);
        else if (wrap == TextureWrap::ClampToEdge)
            u = L::max(L::sub(L::min(L::mul(c, sizeF), sizeF), half), L::floats(0.0f));
        else
            u = L::sub(L::min(L::max(L::mul(c, sizeF), L::floats(0.0f)), sizeF), half);
        const Float floor = L::floor(u);
        weight = L::sub(u, floor);
        // The nearest lanes take the texel of the larger weight (the lower one at a tie).
        weight =
            L::select(nearestLanes, L::select(L::greaterThan(weight, half), L::floats(1.0f), L::floats(0.0f)), weight);
        i0 = L::truncateToInt(floor);
        i1 = L::add(i0, L::ints(1));
        if (wrap == TextureWrap::Repeat && !pot) {
            i0 = L::select(L::lessThan(i0, L::ints(0)), last, i0);  // -1 (and NaN's) wraps to the last
            i1 = L::select(L::lessThan(i0, last), L::add(i0, L::ints(1)), L::ints(0));
        } else if (wrap == TextureWrap::Repeat) {
            i0 = L::bitAnd(i0, last), i1 = L::bitAnd(i1, last);
        } else if (wrap == TextureWrap::ClampToEdge) {
            i1 = L::minInt(i1, last);
        }
    }

    const Texture* texture_;
    Float border_[4];
};

}  // namespace glrenderer
