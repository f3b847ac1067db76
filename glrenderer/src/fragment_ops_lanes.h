#pragma once
// The per-fragment operations on colour words and stencil values in lanes (issue 16), in
// llvmpipe's arithmetic for an RGBA8 buffer: blending in bytes (a product of two bytes
// t = a * b rounded as (t + (t >> 8) + 0x80) >> 8, sums saturating at 255), logic ops on the
// whole word. Included by fragment_stage.h.
#include "glrenderer/fragment_ops.h"

namespace glrenderer {

// The stencil value `stored` after `op`; `ref` for Replace.
template <class L>
typename L::Int stencilAfter(StencilOp op, typename L::Int stored, typename L::Int ref) {
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

// a * b / 255 for bytes a and b, rounded as the reference rounds it.
template <class L>
typename L::Int mulUnorm8(typename L::Int a, typename L::Int b) {
    const typename L::Int t = L::mul(a, b);
    return L::shiftRight(L::add(L::add(t, L::shiftRight(t, 8)), L::ints(0x80)), 8);
}

// Byte `channel` (0 red ... 3 alpha) of colour words.
template <class L>
typename L::Int channelOf(typename L::Int rgba, int channel) {
    const typename L::Int shifted = L::shiftRight(rgba, 8 * channel);
    return channel == 3 ? shifted : L::bitAnd(shifted, L::ints(0xFF));
}

// `value` (a byte of channel `channel`) times blend factor `f`.
template <class L>
typename L::Int blendTerm(BlendFactor f, int channel, typename L::Int value, typename L::Int src, typename L::Int dst) {
    using Int = typename L::Int;
    const Int ones = L::ints(0xFF);
    Int factor;
    switch (f) {
    case BlendFactor::Zero: return L::ints(0);
    case BlendFactor::One: return value;
    case BlendFactor::SrcColor: factor = channelOf<L>(src, channel); break;
    case BlendFactor::OneMinusSrcColor: factor = L::sub(ones, channelOf<L>(src, channel)); break;
    case BlendFactor::DstColor: factor = channelOf<L>(dst, channel); break;
    case BlendFactor::OneMinusDstColor: factor = L::sub(ones, channelOf<L>(dst, channel)); break;
    case BlendFactor::SrcAlpha: factor = channelOf<L>(src, 3); break;
    case BlendFactor::OneMinusSrcAlpha: factor = L::sub(ones, channelOf<L>(src, 3)); break;
    case BlendFactor::DstAlpha: factor = channelOf<L>(dst, 3); break;
    case BlendFactor::OneMinusDstAlpha: factor = L::sub(ones, channelOf<L>(dst, 3)); break;
    case BlendFactor::SrcAlphaSaturate:
        if (channel == 3) return value;  // the factor is 1 on alpha
        factor = L::minUnsigned(channelOf<L>(src, 3), L::sub(ones, channelOf<L>(dst, 3)));
        break;
    default: return value;
    }
    return mulUnorm8<L>(value, factor);
}

// src * srcFactor + dst * dstFactor, per byte.
template <class L>
typename L::Int blend(BlendFactor srcFactor, BlendFactor dstFactor, typename L::Int src, typename L::Int dst) {
    typename L::Int out = L::ints(0);
    for (int c = 0; c < 4; ++c) {
        const typename L::Int sum = L::add(blendTerm<L>(srcFactor, c, channelOf<L>(src, c), src, dst),
                                           blendTerm<L>(dstFactor, c, channelOf<L>(dst, c), src, dst));
        out = L::bitOr(out, L::shiftLeft(L::minUnsigned(sum, L::ints(0xFF)), 8 * c));
    }
    return out;
}

template <class L>
typename L::Int logicOp(LogicOp op, typename L::Int s, typename L::Int d) {
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
