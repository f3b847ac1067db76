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

// Bytes behind glCallLists' array, kept when it is compiled into another list.
std::size_t callListsBytes(GLsizei n, GLenum type) {
    const std::size_t count = n > 0 ? static_cast<std::size_t>(n) : 0;
    switch (type) {
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_2_BYTES: return 2 * count;
    case GL_3_BYTES: return 3 * count;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT:
    case GL_4_BYTES: return 4 * count;
    default: return count;
    }
}

// glCallLists compiled into a list keeps a copy of its names, whose size depends on n and type.
void compiledCallLists(GLsizei n, GLenum type, const void* lists) {
    Context::State* s = currentState();
    if (s && s->lists.compiling()) {
        const auto* bytes = static_cast<const GLubyte*>(lists);
        std::vector<GLubyte> kept =
            bytes ? std::vector<GLubyte>(bytes, bytes + callListsBytes(n, type)) : std::vector<GLubyte>();
        const bool null = !bytes;
        s->lists.add([n, type, kept = std::move(kept), null] { callLists(n, type, null ? nullptr : kept.data()); });
        if (!s->lists.executingWhileCompiling()) return;
    }
    callLists(n, type, lists);
}

const EntryPoint kEntryPoints[] = {
    {"glNewList", entry(+[](GLuint name, GLenum mode) { newList(name, mode); })},
    {"glEndList", entry(+[] { endList(); })},
    {"glCallList", compiled<+[](GLuint name) { callList(name); }>()},
    {"glCallLists", entry(+[](GLsizei n, GLenum type, const void* lists) { compiledCallLists(n, type, lists); })},
    {"glGenLists", entry(+[](GLsizei range) -> GLuint {
         Context::State* s = stateOutsideBeginEnd();
         if (!s) return 0;
         if (range < 0) {
             setError(*s, GL_INVALID_VALUE);
             return 0;
         }
         return s->lists.generate(range);
     })},
    {"glDeleteLists", entry(+[](GLuint first, GLsizei range) {
         Context::State* s = stateOutsideBeginEnd();
         if (!s) return;
         if (range < 0) return setError(*s, GL_INVALID_VALUE);
         s->lists.remove(first, range);
     })},
    {"glIsList", entry(+[](GLuint name) -> GLboolean {
         Context::State* s = stateOutsideBeginEnd();
         return s && s->lists.exists(name) ? GL_TRUE : GL_FALSE;
     })},
    {"glListBase", compiled<+[](GLuint base) {
         if (Context::State* s = stateOutsideBeginEnd()) s->lists.base = base;
     }>()},
};

}  // namespace

std::span<const EntryPoint> listEntryPoints() { return kEntryPoints; }

}  // namespace mygl
