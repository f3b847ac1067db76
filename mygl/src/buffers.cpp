// glClear, glFlush, glFinish and glReadPixels.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include <glrenderer/color_convert.h>

#include "compiled.h"

namespace mygl {
namespace {

void clear(GLbitfield mask) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    constexpr GLbitfield kKnown = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
    if (mask & ~kKnown) return setError(*s, GL_INVALID_VALUE);
    if (s->renderMode != GL_RENDER) return;  // as the reference: selection clears nothing
    drawCachedBitmaps(*s);
    const bool color = (mask & GL_COLOR_BUFFER_BIT) && s->buffers.drawBuffer != GL_NONE;
    // The scissor and the colour, depth and stencil masks apply.
    const glrenderer::FragmentOps& ops = s->draw.fragmentOps;
    s->pipeline.clear({.color = color,
                       .depth = (mask & GL_DEPTH_BUFFER_BIT) && s->draw.depthWrite,
                       .stencil = (mask & GL_STENCIL_BUFFER_BIT) != 0,
                       .rgba = glrenderer::clearColorRgba8(s->clearColor),
                       .depth24 = glrenderer::clearDepth24(s->clearDepth),
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

// Bytes of one pixel in `format`/`type`, or 0 if the pair is not supported.
int bytesPerPixel(GLenum format, GLenum type) {
    if (type == GL_UNSIGNED_BYTE && format == GL_RGBA) return 4;
    if (type == GL_UNSIGNED_BYTE && format == GL_RGB) return 3;
    if (format == GL_DEPTH_COMPONENT && (type == GL_FLOAT || type == GL_UNSIGNED_INT)) return 4;
    if (format == GL_STENCIL_INDEX) {
        if (type == GL_UNSIGNED_BYTE || type == GL_BYTE) return 1;
        if (type == GL_UNSIGNED_SHORT || type == GL_SHORT) return 2;
        return 4;  // GL_UNSIGNED_INT, GL_INT, GL_FLOAT
    }
    return 0;
}

bool isKnownFormat(GLenum format) {
    return format == GL_RGBA || format == GL_RGB || format == GL_DEPTH_COMPONENT || format == GL_RED ||
           format == GL_GREEN || format == GL_BLUE || format == GL_ALPHA || format == GL_LUMINANCE ||
           format == GL_LUMINANCE_ALPHA || format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX;
}

bool isKnownType(GLenum type) {
    return type == GL_UNSIGNED_BYTE || type == GL_BYTE || type == GL_UNSIGNED_SHORT || type == GL_SHORT ||
           type == GL_UNSIGNED_INT || type == GL_INT || type == GL_FLOAT;
}

// A stencil value as an index of `type` (integers as they are, GL_FLOAT as a float).
void writeStencilIndex(std::uint32_t value, GLenum type, std::uint8_t* target) {
    const auto write = [target](auto v) { std::memcpy(target, &v, sizeof v); };
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return write(static_cast<std::uint8_t>(value));
    case GL_UNSIGNED_SHORT: case GL_SHORT: return write(static_cast<std::uint16_t>(value));
    case GL_FLOAT: return write(static_cast<float>(value));
    default: return write(value);
    }
}

// The part of [start, start + length) inside [0, limit), as an offset into the range and a
// count; computed in 64 bits, so no start or length overflows.
struct Span {
    std::int64_t offset = 0, count = 0;
};
Span clipToWindow(GLint start, GLsizei length, int limit) {
    const std::int64_t first = std::max<std::int64_t>(start, 0);
    const std::int64_t last = std::min<std::int64_t>(std::int64_t{start} + length, limit);
    return last > first ? Span{first - start, last - first} : Span{};
}

void readPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void* pixels) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    // The reference checks the size before the format and type.
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    s->updateModelviewProjection();  // the reference validates its state here
    if (!isKnownFormat(format) || !isKnownType(type)) return setError(*s, GL_INVALID_ENUM);
    // An RGBA buffer has no colour indices.
    if (format == GL_COLOR_INDEX) return setError(*s, GL_INVALID_OPERATION);
    const int pixelBytes = bytesPerPixel(format, type);
    if (pixelBytes == 0) return setError(*s, GL_INVALID_OPERATION);  // valid in GL, not offered here
    if (!pixels) return;
    drawCachedBitmaps(*s);
    s->pipeline.finish();
    const auto& fb = s->framebuffer;
    const Span columns = clipToWindow(x, width, fb.width()), rows = clipToWindow(y, height, fb.height());
    const auto align = static_cast<std::size_t>(s->pack.alignment);
    const std::size_t rowBytes = (static_cast<std::size_t>(width) * static_cast<std::size_t>(pixelBytes) + align - 1) / align * align;
    auto* out = static_cast<std::uint8_t*>(pixels);
    // Only the part inside the window is written; the rest of the caller's memory is untouched.
    for (std::int64_t row = rows.offset; row < rows.offset + rows.count; ++row) {
        for (std::int64_t column = columns.offset; column < columns.offset + columns.count; ++column) {
            const auto source = static_cast<std::size_t>((y + row) * fb.width() + (x + column));
            std::uint8_t* target = out + static_cast<std::size_t>(row) * rowBytes + static_cast<std::size_t>(column * pixelBytes);
            if (format == GL_STENCIL_INDEX) {
                writeStencilIndex(fb.stencil()[source], type, target);
            } else if (format == GL_DEPTH_COMPONENT) {
                const std::uint32_t depth24 = fb.depth()[source];
                if (type == GL_FLOAT) {
                    const float value = static_cast<float>(depth24) / static_cast<float>(glrenderer::kDepthMax24);
                    std::memcpy(target, &value, sizeof value);
                } else {
                    const std::uint32_t value = (depth24 << 8) | (depth24 >> 16);  // 24 to 32 bits
                    std::memcpy(target, &value, sizeof value);
                }
            } else {
                std::memcpy(target, &fb.color()[source], static_cast<std::size_t>(pixelBytes));
            }
        }
    }
}

const EntryPoint kEntryPoints[] = {
    {"glClear", compiled<+[](GLbitfield mask) { clear(mask); }>()},
    {"glFlush", entry(+[] {
         if (Context::State* s = stateOutsideBeginEnd()) {
             drawCachedBitmaps(*s);
             s->pipeline.endBatch();
         }
     })},
    {"glFinish", entry(+[] {
         if (Context::State* s = stateOutsideBeginEnd()) {
             drawCachedBitmaps(*s);
             s->pipeline.finish();
         }
     })},
    {"glReadPixels", entry(+[](GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
         readPixels(x, y, w, h, format, type, pixels);
     })},
};

}  // namespace

std::span<const EntryPoint> bufferEntryPoints() { return kEntryPoints; }

}  // namespace mygl
