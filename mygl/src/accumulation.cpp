// glClearAccum, glAccum and the accumulation buffer's part of glClear; the arithmetic is
// glrenderer's (accumulation.h).
#include <algorithm>

#include <glrenderer/accumulation.h>

#include "compiled.h"

namespace mygl {
namespace {

using glrenderer::AccumOp;

std::optional<AccumOp> accumOp(GLenum op) {
    switch (op) {
    case GL_ACCUM: return AccumOp::Accum;
    case GL_LOAD: return AccumOp::Load;
    case GL_RETURN: return AccumOp::Return;
    case GL_MULT: return AccumOp::Mult;
    case GL_ADD: return AccumOp::Add;
    default: return std::nullopt;
    }
}

// The reference's order: the operation is checked first; in GL_SELECT or GL_FEEDBACK nothing
// happens. Without a colour buffer to read (GL_LOAD, GL_ACCUM) or to write (GL_RETURN) the
// accumulation buffer is left as it is.
void accum(GLenum op, GLfloat value) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const std::optional<AccumOp> operation = accumOp(op);
    if (!operation) return setError(*s, GL_INVALID_ENUM);
    if (s->renderMode != GL_RENDER) return;
    const bool reads = *operation == AccumOp::Load || *operation == AccumOp::Accum;
    if (reads && s->buffers.readBuffer == GL_NONE) return;
    if (*operation == AccumOp::Return && s->buffers.drawBuffer == GL_NONE) return;
    drawCachedBitmaps(*s);
    s->pipeline.finish();
    const glrenderer::FragmentOps& ops = s->draw->fragmentOps;
    glrenderer::accumulate(s->framebuffer, ops.scissor, ops.colorMask, *operation, value);
}

// Clamped to [-1, 1] as the reference does it: NaN becomes -1.
float clampToSigned(GLfloat v) { return v > -1.0f ? std::min(v, 1.0f) : -1.0f; }

const EntryPoint kEntryPoints[] = {
    listed<gl::glClearAccum,
           +[](GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
               if (Context::State* s = stateOutsideBeginEnd()) {
                   s->buffers.accumClear = {clampToSigned(r), clampToSigned(g), clampToSigned(b), clampToSigned(a)};
               }
           }>(),
    listed<gl::glAccum, +[](GLenum op, GLfloat value) { accum(op, value); }>(),
};

}  // namespace

void clearAccumBuffer(Context::State& s) {
    glrenderer::clearAccum(s.framebuffer, s.draw->fragmentOps.scissor, s.buffers.accumClear);
}

std::span<const EntryPoint> accumulationEntryPoints() { return kEntryPoints; }

}  // namespace mygl
