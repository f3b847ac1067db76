// glDrawBuffer and glReadBuffer for the context's one colour buffer. The reference's OSMesa
// context is single-buffered (GL_DOUBLEBUFFER false) yet accepts the left buffers, front and
// back: they all name the one buffer; GL_NONE draws or reads nothing.
#include "compiled.h"

namespace mygl {
namespace {

// GL_NO_ERROR for a buffer of this context, GL_INVALID_OPERATION for a buffer it does not
// have (right, auxiliary, a framebuffer object's attachments), GL_INVALID_ENUM for what is no
// buffer at all.
GLenum bufferError(GLenum buffer) {
    constexpr GLenum kColorAttachment0 = 0x8CE0;
    if (buffer >= kColorAttachment0 && buffer < kColorAttachment0 + 32) return GL_INVALID_OPERATION;
    switch (buffer) {
    case GL_NONE:
    case GL_FRONT_LEFT:
    case GL_BACK_LEFT:
    case GL_FRONT:
    case GL_BACK:
    case GL_LEFT:
    case GL_FRONT_AND_BACK: return GL_NO_ERROR;
    case GL_FRONT_RIGHT:
    case GL_BACK_RIGHT:
    case GL_RIGHT:
    case GL_AUX0:
    case GL_AUX1:
    case GL_AUX2:
    case GL_AUX3: return GL_INVALID_OPERATION;
    default: return GL_INVALID_ENUM;
    }
}

void selectBuffer(GLenum buffer, GLenum BufferState::*field) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (const GLenum error = bufferError(buffer); error != GL_NO_ERROR) return setError(*s, error);
    s->buffers.*field = buffer;
    if (field == &BufferState::drawBuffer) updateColorWrites(*s);
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glDrawBuffer, +[](GLenum buffer) { selectBuffer(buffer, &BufferState::drawBuffer); }>(),
    listed<gl::glReadBuffer, +[](GLenum buffer) { selectBuffer(buffer, &BufferState::readBuffer); }>(),
};

}  // namespace

std::span<const EntryPoint> drawBufferEntryPoints() { return kEntryPoints; }

}  // namespace mygl
