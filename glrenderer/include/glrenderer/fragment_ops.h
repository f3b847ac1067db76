#pragma once
// The per-fragment operations after the colour is made (issue 16), as plain values: scissor,
// alpha test, stencil, blending, logic op and the colour mask.
#include <cstdint>

namespace glrenderer {

enum class CompareFunc : std::uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

// glStencilOp's operations; increments and decrements saturate at 0 and 255.
enum class StencilOp : std::uint8_t { Keep, Zero, Replace, Increment, Decrement, Invert };

// glBlendFunc's factors.
enum class BlendFactor : std::uint8_t {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    SrcAlphaSaturate
};

// glLogicOp's operations in GL's enum order (GL_CLEAR = 0x1500 ... GL_SET = 0x150F).
enum class LogicOp : std::uint8_t {
    Clear,
    And,
    AndReverse,
    Copy,
    AndInverted,
    Noop,
    Xor,
    Or,
    Nor,
    Equiv,
    Invert,
    OrReverse,
    CopyInverted,
    OrInverted,
    Nand,
    Set
};

// glScissor's box in window coordinates (y up), used when enabled.
struct ScissorBox {
    bool enabled = false;
    int x = 0, y = 0, width = 0, height = 0;
    bool operator==(const ScissorBox&) const = default;
};

struct StencilState {
    bool enabled = false;
    CompareFunc func = CompareFunc::Always;
    std::uint8_t ref = 0;  // clamped to [0, 255]
    std::uint8_t valueMask = 0xFF, writeMask = 0xFF;
    StencilOp fail = StencilOp::Keep, depthFail = StencilOp::Keep, depthPass = StencilOp::Keep;
    bool operator==(const StencilState&) const = default;
};

struct FragmentOps {
    ScissorBox scissor;
    bool alphaTest = false;
    CompareFunc alphaFunc = CompareFunc::Always;
    std::uint8_t alphaRef = 0;  // the reference value as the reference compares it: a colour byte
    StencilState stencil;
    bool blend = false;
    BlendFactor blendSrc = BlendFactor::One, blendDst = BlendFactor::Zero;
    bool logicOpEnabled = false;
    LogicOp logicOp = LogicOp::Copy;
    std::uint32_t colorMask = 0xFFFFFFFF;  // the bytes of the colour word that are written
    bool operator==(const FragmentOps&) const = default;
};

}  // namespace glrenderer
