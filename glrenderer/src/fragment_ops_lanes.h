#pragma once
// The per-fragment operations on colour words and stencil values in lanes (issue 16), in
// llvmpipe's arithmetic for an RGBA8 buffer: blending in bytes (a product of two bytes
// t = a * b rounded as (t + (t >> 8) + 0x80) >> 8, sums saturating at 255), logic ops on the
// whole word. Included by fragment_stage.h; every function is inlined into the stage, so that a
// constant key leaves only the arithmetic of its factors and operations.
#include "glrenderer/fragment_ops.h"

namespace glrenderer {

// The stencil value `stored` after `op`; `ref` for Replace.
template <class L>
[[gnu::always_inline]] inline typename L::Int stencilAfter(StencilOp op, typename L::Int stored, typename L::Int ref) {
    switch (op) {
    case StencilOp::Keep: return stored;
    case StencilOp::Zero: return L::ints(0);
    case StencilOp::Replace: return ref;
    case StencilOp::Increment: return L::minUnsigned(L::add(stored, L::ints(1)), L::ints(0xFF));
    case StencilOp::Decrement: return L::sub(L::maxUnsigned(stored, L::ints(1)), L::ints(1));
    case StencilOp::Invert: return L::bitXor(stored, L::ints(0xFF));
    }
    return stored;
}

// Blending works on colour words as two words of 16-bit fields holding one byte each: red and
// blue (`rb`), green and alpha (`ga`), so that one operation serves two channels.
template <class L>
struct ChannelPairs {
    typename L::Int rb, ga;
};

template <class L>
[[gnu::always_inline]] inline ChannelPairs<L> pairsOf(typename L::Int rgba) {
    return {L::bitAnd(rgba, L::ints(0x00FF00FF)), L::shiftRight16By8(rgba)};
}

// A byte in both fields.
template <class L>
[[gnu::always_inline]] inline typename L::Int inBothFields(typename L::Int byte) {
    return L::bitOr(byte, L::template shiftLeft<16>(byte));
}

// a * b / 255 in each field, rounded as the reference rounds a product of two bytes (the
// fields hold at most 65025 + 254 + 0x80: no carry into the next).
template <class L>
[[gnu::always_inline]] inline typename L::Int mulUnorm8(typename L::Int a, typename L::Int b) {
    const typename L::Int t = L::mulLow16(a, b);
    return L::shiftRight16By8(L::add(L::add(t, L::shiftRight16By8(t)), L::ints(0x00800080)));
}

// The fields of blend factor `f`, not One or Zero.
template <class L>
[[gnu::always_inline]] inline ChannelPairs<L> factorPairs(BlendFactor f, const ChannelPairs<L>& src,
                                                          const ChannelPairs<L>& dst) {
    using Int = typename L::Int;
    const Int ones = L::ints(0x00FF00FF);
    const auto oneMinus = [&](const ChannelPairs<L>& p) {
        return ChannelPairs<L>{L::sub(ones, p.rb), L::sub(ones, p.ga)};
    };
    const auto alphaOf = [&](const ChannelPairs<L>& p) {
        const Int alpha = inBothFields<L>(L::shiftRight(p.ga, 16));
        return ChannelPairs<L>{alpha, alpha};
    };
    switch (f) {
    case BlendFactor::SrcColor: return src;
    case BlendFactor::OneMinusSrcColor: return oneMinus(src);
    case BlendFactor::DstColor: return dst;
    case BlendFactor::OneMinusDstColor: return oneMinus(dst);
    case BlendFactor::SrcAlpha: return alphaOf(src);
    case BlendFactor::OneMinusSrcAlpha: return oneMinus(alphaOf(src));
    case BlendFactor::DstAlpha: return alphaOf(dst);
    case BlendFactor::OneMinusDstAlpha: return oneMinus(alphaOf(dst));
    case BlendFactor::SrcAlphaSaturate: {  // min(As, 1 - Ad) on RGB, 1 on alpha
        const Int saturate =
            L::minUnsigned(L::shiftRight(src.ga, 16), L::sub(L::ints(0xFF), L::shiftRight(dst.ga, 16)));
        return {inBothFields<L>(saturate), L::bitOr(saturate, L::ints(0x00FF0000))};
    }
    default: return {ones, ones};
    }
}

// `value` times blend factor `f`, in fields.
template <class L>
[[gnu::always_inline]] inline ChannelPairs<L> blendTerm(BlendFactor f, const ChannelPairs<L>& value,
                                                        const ChannelPairs<L>& src, const ChannelPairs<L>& dst) {
    if (f == BlendFactor::Zero) return {L::ints(0), L::ints(0)};
    if (f == BlendFactor::One) return value;
    const ChannelPairs<L> factor = factorPairs<L>(f, src, dst);
    return {mulUnorm8<L>(value.rb, factor.rb), mulUnorm8<L>(value.ga, factor.ga)};
}

// src * srcFactor + dst * dstFactor, per byte, saturating.
template <class L>
[[gnu::always_inline]] inline typename L::Int blend(BlendFactor srcFactor, BlendFactor dstFactor, typename L::Int src,
                                                    typename L::Int dst) {
    const ChannelPairs<L> s = pairsOf<L>(src), d = pairsOf<L>(dst);
    const ChannelPairs<L> a = blendTerm<L>(srcFactor, s, s, d), b = blendTerm<L>(dstFactor, d, s, d);
    const typename L::Int bytes = L::ints(0x00FF00FF);
    const typename L::Int rb = L::minUnsigned16(L::add(a.rb, b.rb), bytes);
    const typename L::Int ga = L::minUnsigned16(L::add(a.ga, b.ga), bytes);
    return L::bitOr(rb, L::template shiftLeft<8>(ga));
}

template <class L>
[[gnu::always_inline]] inline typename L::Int logicOp(LogicOp op, typename L::Int s, typename L::Int d) {
    const typename L::Int ones = L::ints(-1);
    const auto inv = [&](typename L::Int v) { return L::bitXor(v, ones); };
    switch (op) {
    case LogicOp::Clear: return L::ints(0);
    case LogicOp::And: return L::bitAnd(s, d);
    case LogicOp::AndReverse: return L::bitAnd(s, inv(d));
    case LogicOp::Copy: return s;
    case LogicOp::AndInverted: return L::bitAnd(inv(s), d);
    case LogicOp::Noop: return d;
    case LogicOp::Xor: return L::bitXor(s, d);
    case LogicOp::Or: return L::bitOr(s, d);
    case LogicOp::Nor: return inv(L::bitOr(s, d));
    case LogicOp::Equiv: return inv(L::bitXor(s, d));
    case LogicOp::Invert: return inv(d);
    case LogicOp::OrReverse: return L::bitOr(s, inv(d));
    case LogicOp::CopyInverted: return inv(s);
    case LogicOp::OrInverted: return L::bitOr(inv(s), d);
    case LogicOp::Nand: return inv(L::bitAnd(s, d));
    case LogicOp::Set: return ones;
    }
    return s;
}

}  // namespace glrenderer
