// The colour-index calls in an RGBA context: glIndex*, glClearIndex and glIndexMask are accepted,
// kept for glGet and display lists, and change no pixel (glIndexPointer is with the arrays).
#include <array>
#include <cmath>
#include <cstdint>

#include "compiled.h"

namespace mygl {
namespace {

// glIndex is allowed between glBegin and glEnd.
template <class T>
void index(T value) {
    if (Context::State* s = currentState()) s->buffers.currentIndex = static_cast<float>(value);
}

// The reference's (GLuint) conversion of the float: through a 64-bit integer on x86-64, whose
// out-of-range and NaN answer is INT64_MIN (low 32 bits 0).
GLuint truncatedIndex(GLfloat value) {
    const bool inRange = value >= -9.2233720e18f && value < 9.2233720e18f;
    return static_cast<GLuint>(static_cast<std::uint64_t>(inRange ? static_cast<std::int64_t>(value) : INT64_MIN));
}

// clang-format off
#define MYGL_INDEX_ENTRIES(suffix, T)                      \
    listed<gl::glIndex##suffix, +[](T c) { index(c); }>(), \
    listed<gl::glIndex##suffix##v, +[](const T* c) { if (c) index(c[0]); }>()
// clang-format on

const EntryPoint kEntryPoints[] = {
    MYGL_INDEX_ENTRIES(d, GLdouble),
    MYGL_INDEX_ENTRIES(f, GLfloat),
    MYGL_INDEX_ENTRIES(i, GLint),
    MYGL_INDEX_ENTRIES(s, GLshort),
    MYGL_INDEX_ENTRIES(ub, GLubyte),
    listed<gl::glClearIndex,
           +[](GLfloat c) {
               if (Context::State* s = stateOutsideBeginEnd()) s->buffers.clearIndex = truncatedIndex(c);
           }>(),
    listed<gl::glIndexMask,
           +[](GLuint mask) {
               if (Context::State* s = stateOutsideBeginEnd()) s->buffers.indexMask = mask;
           }>(),
};

#undef MYGL_INDEX_ENTRIES

}  // namespace

std::span<const EntryPoint> colorIndexEntryPoints() { return kEntryPoints; }

}  // namespace mygl
