#include "observations.h"

#include <algorithm>
#include <cstdio>

namespace conformance {
namespace {

std::string errorName(GLenum e) {
    switch (e) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "error " + std::to_string(e);
    }
}

// One line of values, without the trailing ones the query left as they were.
template <class T, class Format>
std::string line(const std::string& what, const T* values, std::size_t count, T unwritten, Format format) {
    while (count > 0 && values[count - 1] == unwritten) --count;
    std::string text = what + ":";
    char buffer[64];
    for (std::size_t i = 0; i < count; ++i) {
        format(buffer, sizeof buffer, values[i]);
        text += ' ';
        text += buffer;
    }
    return text;
}

}  // namespace

void Observations::error(const std::string& label) { lines_.push_back(label + " -> " + errorName(glGetError())); }

void Observations::drainErrors() {
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
}

void Observations::floats(const std::string& what, const GLfloat* values, std::size_t count) {
    lines_.push_back(line(what, values, count, kUnwritten, [](char* b, std::size_t n, GLfloat v) {
        std::snprintf(b, n, "%.9g", static_cast<double>(v));
    }));
}

void Observations::doubles(const std::string& what, const GLdouble* values, std::size_t count) {
    lines_.push_back(line(what, values, count, static_cast<GLdouble>(kUnwritten),
                          [](char* b, std::size_t n, GLdouble v) { std::snprintf(b, n, "%.17g", v); }));
}

void Observations::ints(const std::string& what, const GLint* values, std::size_t count) {
    lines_.push_back(line(what, values, count, static_cast<GLint>(kUnwritten),
                          [](char* b, std::size_t n, GLint v) { std::snprintf(b, n, "%d", v); }));
}

void Observations::uints(const std::string& what, const GLuint* values, std::size_t count) {
    lines_.push_back(line(what, values, count, static_cast<GLuint>(static_cast<GLint>(kUnwritten)),
                          [](char* b, std::size_t n, GLuint v) { std::snprintf(b, n, "%u", v); }));
}

void Observations::bytes(const std::string& what, const GLubyte* values, std::size_t count) {
    lines_.push_back(line(what, values, count, GLubyte{0xA5},
                          [](char* b, std::size_t n, GLubyte v) { std::snprintf(b, n, "%u", v); }));
}

void Observations::value(const std::string& what, long long v) { lines_.push_back(what + ": " + std::to_string(v)); }

void Observations::floatsAndInts(const std::string& name, const std::function<void(GLfloat*)>& fv,
                                 const std::function<void(GLint*)>& iv) {
    GLfloat f[4] = {kUnwritten, kUnwritten, kUnwritten, kUnwritten};
    GLint i[4];
    std::fill(std::begin(i), std::end(i), static_cast<GLint>(kUnwritten));
    fv(f);
    iv(i);
    floats(name + "fv", f, 4);
    ints(name + "iv", i, 4);
}

void Observations::get(std::initializer_list<GLenum> pnames) {
    for (GLenum pname : pnames) {
        GLfloat v[16];
        std::fill(std::begin(v), std::end(v), kUnwritten);
        glGetFloatv(pname, v);
        char label[32];
        std::snprintf(label, sizeof label, "glGetFloatv(0x%04X)", pname);
        floats(label, v, 16);
    }
}

std::string firstDifference(const std::vector<std::string>& ours, const std::vector<std::string>& theirs) {
    static const std::string nothing = "(nothing)";
    const std::size_t n = std::max(ours.size(), theirs.size());
    for (std::size_t i = 0; i < n; ++i) {
        const std::string& a = i < ours.size() ? ours[i] : nothing;
        const std::string& b = i < theirs.size() ? theirs[i] : nothing;
        if (a == b) continue;
        std::string text = "#";
        text += std::to_string(i);
        text += ": MyGL ";
        text += a;
        text += " | OSMesa ";
        text += b;
        return text;
    }
    return {};
}

}  // namespace conformance
