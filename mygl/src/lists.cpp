// glNewList, glEndList, glCallList(s), glGenLists, glDeleteLists, glIsList, glListBase.
#include <cstring>
#include <limits>

#include "compiled.h"

namespace mygl {
namespace {

void newList(GLuint name, GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    // Inside a list being compiled the reference reports the nesting whatever the arguments.
    if (s->lists.compiling()) return setError(*s, GL_INVALID_OPERATION);
    if (name == 0) return setError(*s, GL_INVALID_VALUE);
    if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return setError(*s, GL_INVALID_ENUM);
    s->lists.begin(name, mode);
}

void endList() {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (!s->lists.compiling()) return setError(*s, GL_INVALID_OPERATION);
    s->lists.end();
}

// Runs a list. The reference draws what a list holds as draws of their own: the vertices
// before and after it are not merged with the list's (unless a primitive is open across it).
void run(Context::State& s, GLuint name) {
    if (!s.insideBeginEnd) endBatch(s);
    s.lists.call(name);
    if (!s.insideBeginEnd) endBatch(s);
}

// glCallList may be called inside glBegin/glEnd.
void callList(GLuint name) {
    if (Context::State* s = currentState()) run(*s, name);
}

// A float name truncated as the reference's (GLint) cast does on x86, NaN and out-of-range
// values becoming INT_MIN, without the undefined behaviour of the cast.
GLint truncateToInt(GLfloat f) {
    return f >= -2147483648.0f && f < 2147483648.0f ? static_cast<GLint>(f) : std::numeric_limits<GLint>::min();
}

// The i-th name of glCallLists' array in `type`, or false for an unknown type.
bool listName(GLenum type, const void* lists, GLsizei i, GLuint& name) {
    const auto* bytes = static_cast<const GLubyte*>(lists);
    const auto at = [&](auto value) {
        std::memcpy(&value, bytes + static_cast<std::size_t>(i) * sizeof value, sizeof value);
        return value;
    };
    const auto bigEndian = [&](int count) {
        GLuint value = 0;
        for (int b = 0; b < count; ++b) value = value << 8 | bytes[static_cast<std::size_t>(i * count + b)];
        return value;
    };
    switch (type) {
    case GL_BYTE: name = static_cast<GLuint>(at(GLbyte{})); return true;
    case GL_UNSIGNED_BYTE: name = at(GLubyte{}); return true;
    case GL_SHORT: name = static_cast<GLuint>(at(GLshort{})); return true;
    case GL_UNSIGNED_SHORT: name = at(GLushort{}); return true;
    case GL_INT: name = static_cast<GLuint>(at(GLint{})); return true;
    case GL_UNSIGNED_INT: name = at(GLuint{}); return true;
    case GL_FLOAT: name = static_cast<GLuint>(truncateToInt(at(GLfloat{}))); return true;
    case GL_2_BYTES: name = bigEndian(2); return true;
    case GL_3_BYTES: name = bigEndian(3); return true;
    case GL_4_BYTES: name = bigEndian(4); return true;
    default: return false;
    }
}

void callLists(GLsizei n, GLenum type, const void* lists) {
    Context::State* s = currentState();
    if (!s) return;
    GLuint probe = 0;
    if (!listName(type, &probe, 0, probe)) return setError(*s, GL_INVALID_ENUM);
    if (n < 0) return setError(*s, GL_INVALID_VALUE);
    if (!lists) return;
    for (GLsizei i = 0; i < n; ++i) {
        GLuint name = 0;
        listName(type, lists, i, name);
        run(*s, s->lists.base + name);
    }
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glNewList, +[](GLuint name, GLenum mode) { newList(name, mode); }>(),
    listed<gl::glEndList, +[] { endList(); }>(),
    listed<gl::glCallList, +[](GLuint name) { callList(name); }>(),
    listed<gl::glCallLists, +[](GLsizei n, GLenum type, const void* lists) { callLists(n, type, lists); }>(),
    listed<gl::glGenLists,
           +[](GLsizei range) -> GLuint {
               Context::State* s = stateOutsideBeginEnd();
               if (!s) return 0;
               if (range < 0) {
                   setError(*s, GL_INVALID_VALUE);
                   return 0;
               }
               return s->lists.generate(range);
           }>(),
    listed<gl::glDeleteLists,
           +[](GLuint first, GLsizei range) {
               Context::State* s = stateOutsideBeginEnd();
               if (!s) return;
               if (range < 0) return setError(*s, GL_INVALID_VALUE);
               s->lists.remove(first, range);
           }>(),
    listed<gl::glIsList,
           +[](GLuint name) -> GLboolean {
               Context::State* s = stateOutsideBeginEnd();
               return s && s->lists.exists(name) ? GL_TRUE : GL_FALSE;
           }>(),
    listed<gl::glListBase,
           +[](GLuint base) {
               if (Context::State* s = stateOutsideBeginEnd()) s->lists.base = base;
           }>(),
};

}  // namespace

std::span<const EntryPoint> listEntryPoints() { return kEntryPoints; }

}  // namespace mygl
