// glClear, glFlush, glFinish and glReadPixels (read_pixels.cpp).
#include <algorithm>
#include <cstdint>
#include <cstring>

#include <glrenderer/color_convert.h>

#include "compiled.h"
#include "read_pixels.h"

namespace mygl {
namespace {

void clear(GLbitfield mask) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    constexpr GLbitfield kKnown =
        GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
    if (mask & ~kKnown) return setError(*s, GL_INVALID_VALUE);
    if (s->renderMode != GL_RENDER) return;  // as the reference: selection clears nothing
    drawCachedBitmaps(*s);
    const bool color = (mask & GL_COLOR_BUFFER_BIT) && s->buffers.drawBuffer != GL_NONE;
    // The scissor and the colour, depth and stencil masks apply.
    const glrenderer::FragmentOps& ops = s->draw->fragmentOps;
    // The reference's state tracker clears depth with a quad when the scissor box leaves part of
    // the window out, or when the stencil is cleared with it under a partial write mask
    // (st_Clear: depth and stencil are cleared together): its depth takes the float path.
    const glrenderer::ScissorBox& box = ops.scissor;
    const bool scissored = box.enabled && (box.x > 0 || box.y > 0 || box.x + box.width < s->framebuffer.width() ||
                                           box.y + box.height < s->framebuffer.height());
    const bool stencilMasked = (mask & GL_STENCIL_BUFFER_BIT) && (ops.stencil.writeMask & 0xFFu) != 0xFFu;
    const std::uint32_t depth24 = scissored || stencilMasked ? glrenderer::quadClearDepth24(s->clearDepth)
                                                             : glrenderer::clearDepth24(s->clearDepth);
    s->pipeline.clear({.color = color,
                       .depth = (mask & GL_DEPTH_BUFFER_BIT) && s->draw->depthWrite,
                       .stencil = (mask & GL_STENCIL_BUFFER_BIT) != 0,
                       .rgba = glrenderer::clearColorRgba8(s->clearColor),
                       .depth24 = depth24,
                       .colorMask = ops.colorMask,
                       .stencilValue = static_cast<std::uint8_t>(s->fragmentOps.clearStencil & 0xFF),
                       .stencilMask = ops.stencil.writeMask,
                       .scissor = ops.scissor});
    if (color) s->pipeline.resetStats();  // a frame's counts start at its clear, as the course did
    if (mask & GL_ACCUM_BUFFER_BIT) {
        s->pipeline.finish();
        clearAccumBuffer(*s);
    }
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glClear, +[](GLbitfield mask) { clear(mask); }>(),
    listed<gl::glFlush,
           +[] {
               if (Context::State* s = stateOutsideBeginEnd()) {
                   drawCachedBitmaps(*s);
                   s->pipeline.endBatch();
               }
           }>(),
    listed<gl::glFinish,
           +[] {
               if (Context::State* s = stateOutsideBeginEnd()) {
                   drawCachedBitmaps(*s);
                   s->pipeline.finish();
               }
           }>(),
    listed<gl::glReadPixels, +[](GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type,
                                 void* pixels) { readPixels(x, y, w, h, format, type, pixels); }>(),
};

}  // namespace

std::span<const EntryPoint> bufferEntryPoints() { return kEntryPoints; }

}  // namespace mygl
