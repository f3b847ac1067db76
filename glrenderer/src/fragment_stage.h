#pragma once
// The fragment stage, written once over a lane type L (simd_scalar.h, simd_avx2.h,
// simd_avx512.h: L::kCount pixels per block) and a key. Included only by the files that compile
// it for one width (fragment_paths_*.cpp). Every lane performs the scalar operations in the same
// order (the planes' two fmas, one IEEE division, the conversions' clamps), so the bits do not
// depend on the width; with a constant key the compiler drops every step the key turns off.
#include <cstddef>
#include <cstdint>

#include "fragment_fog.h"
#include "fragment_inputs.h"
#include "fragment_ops_lanes.h"
#include "fragment_texture.h"
#include "lane_clamp.h"
#include "plane_lanes.h"

namespace glrenderer {

// The reference's fragment colour conversion (color_convert.h, fragmentToUnorm8) in lanes.
template <class L>
typename L::Int fragmentToUnorm8(typename L::Float v) {
    const typename L::Float biased = L::add(L::mul(clampUnit<L>(v), L::floats(255.0f / 256.0f)), L::floats(32768.0f));
    return L::bitAnd(L::bitsOf(biased), L::ints(0xFF));
}

// A primitive's fragment inputs broadcast to the lanes, and what the stage computes from them
// for a block of pixels at (x, y).
// `ColumnsFixed`: its colour, depth and fog planes for blocks that all lie on one set of columns
// (PlaneLanes; fixColumns).
template <class L, bool ColumnsFixed = false>
class FragmentLanes {
public:
    using Float = typename L::Float;
    using Int = typename L::Int;

    // `key`: the routine's (a fast path's constant). `framebufferHeight` turns internal rows into
    // the window rows the polygon stipple reads. Inlined into each routine, where the planes its
    // key never reads are not broadcast (called out of line, from the fifth routine calling it, it
    // was 14% of a mesh's CPU).
    [[gnu::always_inline]] FragmentLanes(const FragmentKey& key, const FragmentInputs& in, int framebufferHeight)
        : depth_(in.depth()),
          invW_(in.invW()),
          red_(in.color[0]),
          green_(in.color[1]),
          blue_(in.color[2]),
          alpha_(in.color[3]),
          secondaryRed_(in.secondaryColor[0]),
          secondaryGreen_(in.secondaryColor[1]),
          secondaryBlue_(in.secondaryColor[2]),
          flat_(L::ints(static_cast<int>(in.flatColor))),
          fogCoord_(in.fogCoord),
          fog_(in.fog),
          depthOffset_(L::floats(in.depthOffset)),
          alphaRef_(L::ints(in.ops.alphaRef)),
          stencilRef_(L::ints(in.ops.stencilRef)),
          stencilValueMask_(L::ints(in.ops.stencilValueMask)),
          stencilWriteMask_(L::ints(in.ops.stencilWriteMask)),
          colorMask_(L::ints(static_cast<int>(in.ops.colorMask))),
          texture_(key, in),
          polygonStipple_(in.polygonStipple),
          lastRow_(framebufferHeight - 1) {}

    // The values of primitive `in` of the same draw constants (sameDrawConstants) in the lanes
    // `lanes` only: its planes, flat colour and depth offset, for a block that holds fragments of
    // several primitives (shadePackedRun).
    [[gnu::always_inline]] void take(const FragmentInputs& in, typename L::Mask lanes) {
        depth_.take(in.depth(), lanes), invW_.take(in.invW(), lanes);
        red_.take(in.color[0], lanes), green_.take(in.color[1], lanes);
        blue_.take(in.color[2], lanes), alpha_.take(in.color[3], lanes);
        secondaryRed_.take(in.secondaryColor[0], lanes), secondaryGreen_.take(in.secondaryColor[1], lanes);
        secondaryBlue_.take(in.secondaryColor[2], lanes), fogCoord_.take(in.fogCoord, lanes);
        flat_ = L::select(lanes, L::ints(static_cast<int>(in.flatColor)), flat_);
        depthOffset_ = L::select(lanes, L::floats(in.depthOffset), depthOffset_);
        texture_.take(in, lanes);
    }

    // The columns of every later block (ColumnsFixed only).
    [[gnu::always_inline]] void fixColumns(Float x) {
        for (auto* plane : {&depth_, &invW_, &red_, &green_, &blue_, &alpha_, &secondaryRed_, &secondaryGreen_,
                            &secondaryBlue_, &fogCoord_}) {
            plane->fixColumns(x);
        }
    }

    // The per-fragment operations' constants (issue 16).
    Int alphaRef() const { return alphaRef_; }
    Int stencilValueMask() const { return stencilValueMask_; }
    Int stencilWriteMask() const { return stencilWriteMask_; }
    Int colorMask() const { return colorMask_; }

    // The lanes of `live` the polygon stipple keeps: bit 31 - (x & 31) of the pattern's row
    // (window y & 31), y counted from the bottom. One lane at a time: only stippled draws pay.
    typename L::Mask polygonStippled(Float x, Float y, typename L::Mask live) const {
        float xs[L::kCount], ys[L::kCount], kept[L::kCount];
        L::storeFloats(xs, x), L::storeFloats(ys, y);
        for (int i = 0; i < L::kCount; ++i) {
            const int windowY = lastRow_ - static_cast<int>(ys[i]);
            const std::uint32_t row = (*polygonStipple_)[static_cast<std::size_t>(windowY & 31)];
            kept[i] = (row >> (31 - (static_cast<int>(xs[i]) & 31))) & 1u ? 1.0f : 0.0f;
        }
        return L::both(live, L::lessThan(L::floats(0.5f), L::loadFloats(kept)));
    }

    // The stencil reference of the lanes: the draw's, or a stencil image's texels.
    Int stencilRef(const FragmentKey& key, Float x, Float y, typename L::Mask live) const {
        if (key.texelUse == TexelUse::Stencil) return texture_.word(key, x, y, live);
        return stencilRef_;
    }

    // 24-bit window depth: round(clamp(z) * (2^24 - 1)), ties to even, or a depth image's texels.
    // Polygon offset adds the primitive's depth offset to z first.
    Int depth24(const FragmentKey& key, Float x, Float y, typename L::Mask live) const {
        if (key.texelUse == TexelUse::Depth) return texture_.word(key, x, y, live);
        Float z = depth_.at(x, y);
        if (key.depthOffset) z = L::add(z, depthOffset_);
        return L::roundToInt(L::mul(clampUnit<L>(z), L::floats(16777215.0f)));
    }

    // The colour words of the lanes `live`, packed R, G, B, A from the low byte. `Quads`: how the
    // lanes lie on the level of detail's quads (the block's kQuadLanes).
    template <QuadLanes Quads>
    [[gnu::always_inline]] inline Int rgba(const FragmentKey& key, Float x, Float y, typename L::Mask live) const {
        const bool textured = key.texturesColor();
        if (key.shading == Shading::Flat && key.fog == FogMode::Off && !textured && !key.colorSum) return flat_;
        Float r = red_.at(x, y), g = green_.at(x, y), b = blue_.at(x, y), a = alpha_.at(x, y);
        Float w{};
        if (key.shading == Shading::Perspective || key.fog != FogMode::Off || textured) {
            w = L::div(L::floats(1.0f), invW_.at(x, y));
            if (key.shading == Shading::Perspective)
                r = L::mul(r, w), g = L::mul(g, w), b = L::mul(b, w), a = L::mul(a, w);
        }
        // The texture environment, then the secondary colour, unclamped (the conversion clamps the sum).
        Float secondary[3];
        if (key.colorSum) {
            secondary[0] = secondaryRed_.at(x, y), secondary[1] = secondaryGreen_.at(x, y),
            secondary[2] = secondaryBlue_.at(x, y);
            if (key.shading == Shading::Perspective) {
                for (Float& s : secondary) s = L::mul(s, w);
            }
        }
        if (textured) {
            Float texel[4], c[4] = {r, g, b, a};
            texture_.template sample<Quads>(key, x, y, w, live, texel);
            applyTextureEnv<L>(key, texel, texture_.envColor(), key.colorSum ? secondary : nullptr, c);
            r = c[0], g = c[1], b = c[2], a = c[3];
        } else if (key.colorSum) {
            r = L::add(r, secondary[0]), g = L::add(g, secondary[1]), b = L::add(b, secondary[2]);
        }
        // Fog, after them: alpha keeps its value.
        if (key.fog != FogMode::Off) {
            const Float f = fog_.factor(key.fog, L::mul(fogCoord_.at(x, y), w));
            r = fog_.apply(0, f, r), g = fog_.apply(1, f, g), b = fog_.apply(2, f, b);
        }
        const Int alpha =
            key.alphaOne ? L::ints(static_cast<int>(0xFF000000u)) : L::template shiftLeft<24>(fragmentToUnorm8<L>(a));
        return L::bitOr(L::bitOr(fragmentToUnorm8<L>(r), L::template shiftLeft<8>(fragmentToUnorm8<L>(g))),
                        L::bitOr(L::template shiftLeft<16>(fragmentToUnorm8<L>(b)), alpha));
    }

private:
    PlaneLanes<L, ColumnsFixed> depth_, invW_, red_, green_, blue_, alpha_, secondaryRed_, secondaryGreen_,
        secondaryBlue_;
    Int flat_;
    PlaneLanes<L, ColumnsFixed> fogCoord_;
    FogLanes<L> fog_;
    Float depthOffset_;
    Int alphaRef_, stencilRef_, stencilValueMask_, stencilWriteMask_, colorMask_;
    TextureLanes<L> texture_;
    const PolygonStipplePattern* polygonStipple_;
    int lastRow_;
};

// Lanes on consecutive pixels of a row: lane i is pixel first + i of the buffers. A whole
// block (every lane inside the span, or the block inside the tile: blockInOneTile) uses plain
// loads and stores where masked ones are slow.
template <class L>
class RowBlock {
public:
    using Int = typename L::Int;
    using Mask = typename L::Mask;

    // Under a key that samples a level of detail, the first lane is at an even x (shadeSpan):
    // lanes 2k and 2k + 1 are one row of a 2 x 2 quad.
    static constexpr QuadLanes kQuadLanes = L::kCount > 1 ? QuadLanes::RowPairs : QuadLanes::PerLane;

    // `first` may lie a few pixels before the buffer, where only masked-off lanes point.
    RowBlock(std::ptrdiff_t first, bool whole) : first_(first), whole_(whole) {}

    Int load(const std::uint32_t* buffer, Mask lanes) const {
        if constexpr (!L::kCheapMasks) {
            if (whole_) return L::loadWhole(buffer + first_);
        }
        return L::load(buffer + first_, lanes);
    }
    void store(std::uint32_t* buffer, Mask lanes, Int values) const {
        if constexpr (!L::kCheapMasks) {
            if (whole_) {
                const Int merged = L::all(lanes) ? values : L::select(lanes, values, L::loadWhole(buffer + first_));
                return L::storeWhole(buffer + first_, merged);
            }
        }
        L::store(buffer + first_, lanes, values);
    }

private:
    std::ptrdiff_t first_;
    bool whole_;
};

// The framebuffer's planes, from their first pixel.
struct PixelBuffers {
    std::uint32_t* color;
    std::uint32_t* depth;
    std::uint32_t* stencil;
};

// The stencil test of a block: the lanes of `live` that pass, and into `updated` the stored
// values changed by the stencil-fail operation.
template <class L, bool ColumnsFixed>
[[gnu::always_inline]] inline typename L::Mask stencilTest(const FragmentKey& key,
                                                           const FragmentLanes<L, ColumnsFixed>& in,
                                                           typename L::Mask live, typename L::Int ref,
                                                           typename L::Int stored, typename L::Int& updated) {
    const typename L::Int mask = in.stencilValueMask();
    const typename L::Mask pass = L::compare(key.stencilFunc, live, L::bitAnd(ref, mask), L::bitAnd(stored, mask));
    if (key.stencilFail != StencilOp::Keep) {
        updated = L::select(L::butNot(live, pass), stencilAfter<L>(key.stencilFail, stored, ref), updated);
    }
    return pass;
}

// The stored colour words `dst` under the colour `src` of the fragments: blending, the logic op
// and the colour mask of the key.
template <class L, bool ColumnsFixed>
[[gnu::always_inline]] inline typename L::Int combineWithStored(const FragmentKey& key,
                                                                const FragmentLanes<L, ColumnsFixed>& in,
                                                                typename L::Int src, typename L::Int dst) {
    if (key.blendSrc != BlendFactor::One || key.blendDst != BlendFactor::Zero) {
        src = blend<L>(key.blendSrc, key.blendDst, src, dst);
    }
    if (key.logicOp != LogicOp::Copy) src = logicOp<L>(key.logicOp, src, dst);
    if (key.colorMask)
        src = L::bitOr(L::bitAnd(src, in.colorMask()), L::bitAnd(dst, L::bitXor(in.colorMask(), L::ints(-1))));
    return src;
}

// The fragment stage on one block of pixels at (x, y), `covered` the lanes the primitive covers,
// in GL's order. Returns the lanes written. Colour is computed after the tests unless the alpha
// test needs it: the fragments that fail need none.
template <class L, class Block, bool ColumnsFixed>
[[gnu::always_inline]] inline typename L::Mask shadeBlock(const FragmentKey& key,
                                                          const FragmentLanes<L, ColumnsFixed>& in, typename L::Float x,
                                                          typename L::Float y, typename L::Mask covered,
                                                          const Block& block, const PixelBuffers& buffers) {
    using Int = typename L::Int;
    typename L::Mask live = key.polygonStipple ? in.polygonStippled(x, y, covered) : covered;
    // The texture environment, then fog (FragmentLanes::rgba) make the colour.
    // The scissor test was done on the primitive's bounds (drawableRect).
    Int rgba{};
    if (key.alphaFunc != CompareFunc::Always) {  // in bytes, as the reference compares
        rgba = in.template rgba<Block::kQuadLanes>(key, x, y, live);
        live = L::compare(key.alphaFunc, live, L::shiftRight(rgba, 24), in.alphaRef());
    }
    Int stencil{}, updatedStencil{}, stencilRef{};
    const typename L::Mask stencilLanes = live;  // the lanes whose stencil value an operation may change
    if (key.stencilTest) {
        stencilRef = in.stencilRef(key, x, y, live);
        stencil = updatedStencil = block.load(buffers.stencil, live);
        live = stencilTest<L>(key, in, live, stencilRef, stencil, updatedStencil);
    }
    if (key.deferredPass == DeferredPass::Visibility) {
        // The depth test against the depths without their marks; the depths written marked.
        const Int z = in.depth24(key, x, y, live);
        const Int stored = L::bitAnd(block.load(buffers.depth, live), L::ints(kDeferredMark - 1));
        live = L::compare(key.depthFunc, live, z, stored);
        block.store(buffers.depth, live, L::bitOr(z, L::ints(kDeferredMark)));
        return live;
    }
    if (key.deferredPass == DeferredPass::Shade) {
        // The pixels whose last winner this fragment is: their marked depth is its own.
        const Int z = in.depth24(key, x, y, live);
        live =
            L::compare(CompareFunc::Equal, live, L::bitOr(z, L::ints(kDeferredMark)), block.load(buffers.depth, live));
        block.store(buffers.depth, live, z);
    } else if (key.depthTest) {
        const Int z = in.depth24(key, x, y, live);
        const typename L::Mask depthPass = L::compare(key.depthFunc, live, z, block.load(buffers.depth, live));
        if (key.stencilDepthFail != StencilOp::Keep) {
            updatedStencil = L::select(L::butNot(live, depthPass),
                                       stencilAfter<L>(key.stencilDepthFail, stencil, stencilRef), updatedStencil);
        }
        live = depthPass;
        if (key.depthWrite) block.store(buffers.depth, live, z);
    }
    if (key.stencilTest) {
        if (key.stencilDepthPass != StencilOp::Keep) {
            updatedStencil =
                L::select(live, stencilAfter<L>(key.stencilDepthPass, stencil, stencilRef), updatedStencil);
        }
        const Int writeMask = in.stencilWriteMask();
        const Int kept = L::bitAnd(stencil, L::bitXor(writeMask, L::ints(-1)));
        block.store(buffers.stencil, stencilLanes, L::bitOr(kept, L::bitAnd(updatedStencil, writeMask)));
    }
    if (L::none(live)) return live;
    if (key.alphaFunc == CompareFunc::Always) rgba = in.template rgba<Block::kQuadLanes>(key, x, y, live);
    if (key.readsColor()) rgba = combineWithStored<L>(key, in, rgba, block.load(buffers.color, live));
    block.store(buffers.color, live, rgba);
    return live;
}

}  // namespace glrenderer
