// glScissor, glAlphaFunc, glStencilFunc, glStencilOp, glStencilMask, glClearStencil,
// glBlendFunc, glLogicOp, glColorMask and their enables (issue 16).
#include <algorithm>

#include <glrenderer/color_convert.h>

#include "clamp_to_unit.h"
#include "compiled.h"
#include "fragment_ops_state.h"

namespace mygl {
namespace {

using glrenderer::BlendFactor;
using glrenderer::CompareFunc;
using glrenderer::StencilOp;

bool isCompareFunc(GLenum func) { return func >= GL_NEVER && func <= GL_ALWAYS; }
CompareFunc compareFunc(GLenum func) { return static_cast<CompareFunc>(func - GL_NEVER); }

std::optional<StencilOp> stencilOp(GLenum op) {
    switch (op) {
    case GL_KEEP: return StencilOp::Keep;
    case GL_ZERO: return StencilOp::Zero;
    case GL_REPLACE: return StencilOp::Replace;
    case GL_INCR: return StencilOp::Increment;
    case GL_DECR: return StencilOp::Decrement;
    case GL_INVERT: return StencilOp::Invert;
    default: return std::nullopt;
    }
}

// Every factor on either side, as the reference accepts them.
std::optional<BlendFactor> blendFactor(GLenum factor) {
    switch (factor) {
    case GL_ZERO: return BlendFactor::Zero;
    case GL_ONE: return BlendFactor::One;
    case GL_SRC_COLOR: return BlendFactor::SrcColor;
    case GL_ONE_MINUS_SRC_COLOR: return BlendFactor::OneMinusSrcColor;
    case GL_DST_COLOR: return BlendFactor::DstColor;
    case GL_ONE_MINUS_DST_COLOR: return BlendFactor::OneMinusDstColor;
    case GL_SRC_ALPHA: return BlendFactor::SrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return BlendFactor::OneMinusSrcAlpha;
    case GL_DST_ALPHA: return BlendFactor::DstAlpha;
    case GL_ONE_MINUS_DST_ALPHA: return BlendFactor::OneMinusDstAlpha;
    case GL_SRC_ALPHA_SATURATE: return BlendFactor::SrcAlphaSaturate;
    default: return std::nullopt;
    }
}

// Sets the pipeline's operations, ending the batch only when they change.
void update(Context::State& s, const glrenderer::FragmentOps& ops) {
    if (s.draw->fragmentOps != ops) endBatch(s);
    s.draw.edit().fragmentOps = ops;
}

void scissor(GLint x, GLint y, GLsizei width, GLsizei height) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.scissor = {ops.scissor.enabled, x, y, width, height};
    update(*s, ops);
}

void alphaFunc(GLenum func, GLclampf ref) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (!isCompareFunc(func)) return setError(*s, GL_INVALID_ENUM);
    s->fragmentOps.alphaFunc = func;
    s->fragmentOps.alphaRef = clampToUnit(ref);
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.alphaFunc = compareFunc(func);
    ops.alphaRef = glrenderer::fragmentToUnorm8(s->fragmentOps.alphaRef);
    update(*s, ops);
}

void stencilFunc(GLenum func, GLint ref, GLuint mask) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (!isCompareFunc(func)) return setError(*s, GL_INVALID_ENUM);
    FragmentOpsParameters& p = s->fragmentOps;
    p.stencilFunc = func, p.stencilRef = ref, p.stencilValueMask = mask;
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.stencil.func = compareFunc(func);
    ops.stencil.ref = static_cast<std::uint8_t>(std::clamp(ref, 0, 0xFF));
    ops.stencil.valueMask = static_cast<std::uint8_t>(mask & 0xFF);
    update(*s, ops);
}

void setStencilOp(GLenum fail, GLenum depthFail, GLenum depthPass) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const auto f = stencilOp(fail), zf = stencilOp(depthFail), zp = stencilOp(depthPass);
    if (!f || !zf || !zp) return setError(*s, GL_INVALID_ENUM);
    FragmentOpsParameters& p = s->fragmentOps;
    p.stencilFail = fail, p.stencilDepthFail = depthFail, p.stencilDepthPass = depthPass;
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.stencil.fail = *f, ops.stencil.depthFail = *zf, ops.stencil.depthPass = *zp;
    update(*s, ops);
}

void stencilMask(GLuint mask) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    s->fragmentOps.stencilWriteMask = mask;
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.stencil.writeMask = static_cast<std::uint8_t>(mask & 0xFF);
    update(*s, ops);
}

void blendFunc(GLenum src, GLenum dst) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const auto sf = blendFactor(src), df = blendFactor(dst);
    if (!sf || !df) return setError(*s, GL_INVALID_ENUM);
    s->fragmentOps.blendSrc = src, s->fragmentOps.blendDst = dst;
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.blendSrc = *sf, ops.blendDst = *df;
    update(*s, ops);
}

void logicOp(GLenum op) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (op < GL_CLEAR || op > GL_SET) return setError(*s, GL_INVALID_ENUM);
    s->fragmentOps.logicOp = op;
    glrenderer::FragmentOps ops = s->draw->fragmentOps;
    ops.logicOp = static_cast<glrenderer::LogicOp>(op - GL_CLEAR);
    update(*s, ops);
}

void colorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    s->fragmentOps.colorMask = {r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
    updateColorWrites(*s);
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glScissor, +[](GLint x, GLint y, GLsizei w, GLsizei h) { scissor(x, y, w, h); }>(),
    listed<gl::glAlphaFunc, +[](GLenum func, GLclampf ref) { alphaFunc(func, ref); }>(),
    listed<gl::glStencilFunc, +[](GLenum func, GLint ref, GLuint mask) { stencilFunc(func, ref, mask); }>(),
    listed<gl::glStencilOp, +[](GLenum fail, GLenum zfail, GLenum zpass) { setStencilOp(fail, zfail, zpass); }>(),
    listed<gl::glStencilMask, +[](GLuint mask) { stencilMask(mask); }>(),
    listed<gl::glClearStencil,
           +[](GLint value) {
               if (Context::State* s = stateOutsideBeginEnd()) s->fragmentOps.clearStencil = value;
           }>(),
    listed<gl::glBlendFunc, +[](GLenum src, GLenum dst) { blendFunc(src, dst); }>(),
    listed<gl::glLogicOp, +[](GLenum op) { logicOp(op); }>(),
    listed<gl::glColorMask, +[](GLboolean r, GLboolean g, GLboolean b, GLboolean a) { colorMask(r, g, b, a); }>(),
};

}  // namespace

bool setFragmentOpsCapability(Context::State& s, GLenum cap, bool enabled) {
    if (cap == GL_INDEX_LOGIC_OP) {
        s.fragmentOps.indexLogicOp = enabled;
        return true;
    }
    glrenderer::FragmentOps ops = s.draw->fragmentOps;
    switch (cap) {
    case GL_SCISSOR_TEST: ops.scissor.enabled = enabled; break;
    case GL_ALPHA_TEST: ops.alphaTest = enabled; break;
    case GL_STENCIL_TEST: ops.stencil.enabled = enabled; break;
    case GL_BLEND: ops.blend = enabled; break;
    case GL_COLOR_LOGIC_OP: ops.logicOpEnabled = enabled; break;
    default: return false;
    }
    update(s, ops);
    return true;
}

std::optional<bool> fragmentOpsCapability(const Context::State& s, GLenum cap) {
    const glrenderer::FragmentOps& ops = s.draw->fragmentOps;
    switch (cap) {
    case GL_SCISSOR_TEST: return ops.scissor.enabled;
    case GL_ALPHA_TEST: return ops.alphaTest;
    case GL_STENCIL_TEST: return ops.stencil.enabled;
    case GL_BLEND: return ops.blend;
    case GL_COLOR_LOGIC_OP: return ops.logicOpEnabled;
    case GL_INDEX_LOGIC_OP: return s.fragmentOps.indexLogicOp;
    default: return std::nullopt;
    }
}

std::optional<std::vector<double>> fragmentOpsQuery(const Context::State& s, GLenum name) {
    const FragmentOpsParameters& p = s.fragmentOps;
    const glrenderer::ScissorBox& box = s.draw->fragmentOps.scissor;
    switch (name) {
    case GL_SCISSOR_BOX:
        return std::vector<double>{double(box.x), double(box.y), double(box.width), double(box.height)};
    case GL_ALPHA_TEST_FUNC: return std::vector<double>{double(p.alphaFunc)};
    case GL_ALPHA_TEST_REF: return std::vector<double>{p.alphaRef};
    case GL_STENCIL_FUNC: return std::vector<double>{double(p.stencilFunc)};
    case GL_STENCIL_REF: return std::vector<double>{double(std::clamp(p.stencilRef, 0, 0xFF))};
    case GL_STENCIL_VALUE_MASK: return std::vector<double>{double(p.stencilValueMask)};
    case GL_STENCIL_WRITEMASK: return std::vector<double>{double(p.stencilWriteMask)};
    case GL_STENCIL_FAIL: return std::vector<double>{double(p.stencilFail)};
    case GL_STENCIL_PASS_DEPTH_FAIL: return std::vector<double>{double(p.stencilDepthFail)};
    case GL_STENCIL_PASS_DEPTH_PASS: return std::vector<double>{double(p.stencilDepthPass)};
    case GL_STENCIL_CLEAR_VALUE: return std::vector<double>{double(p.clearStencil)};
    case GL_BLEND_SRC: return std::vector<double>{double(p.blendSrc)};
    case GL_BLEND_DST: return std::vector<double>{double(p.blendDst)};
    case GL_LOGIC_OP_MODE: return std::vector<double>{double(p.logicOp)};
    case GL_COLOR_WRITEMASK: {
        std::vector<double> mask;
        for (bool c : p.colorMask) mask.push_back(c ? 1.0 : 0.0);
        return mask;
    }
    default: return std::nullopt;
    }
}

std::span<const EntryPoint> fragmentOpsEntryPoints() { return kEntryPoints; }

void updateColorWrites(Context::State& s) {
    glrenderer::FragmentOps ops = s.draw->fragmentOps;
    ops.colorMask = 0;
    if (s.buffers.drawBuffer != GL_NONE) {
        for (int c = 0; c < 4; ++c) {
            if (s.fragmentOps.colorMask[static_cast<std::size_t>(c)]) ops.colorMask |= 0xFFu << (8 * c);
        }
    }
    update(s, ops);
}

}  // namespace mygl
