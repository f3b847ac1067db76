#include "gl_call.h"

#include <glad/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <unordered_map>

#include "gl_enum_names.h"
#include "image_calls.h"

namespace fuzz {
namespace {

struct ArgumentReader {
    const std::vector<double>& args;
    std::size_t next = 0;
    double take() { return next < args.size() ? args[next++] : 0.0; }
};

// A double to the parameter's type; integers saturate (NaN gives 0) so that no stream, however
// it was edited, converts out of range.
template <class T>
T fromDouble(double v) {
    if constexpr (std::is_floating_point_v<T>) {
        return static_cast<T>(v);
    } else {
        if (std::isnan(v)) return 0;
        return static_cast<T>(std::clamp(v, static_cast<double>(std::numeric_limits<T>::lowest()),
                                         static_cast<double>(std::numeric_limits<T>::max())));
    }
}

template <class T>
std::string typeName() {
    if constexpr (std::is_same_v<T, GLfloat>)
        return "GLfloat";
    else if constexpr (std::is_same_v<T, GLdouble>)
        return "GLdouble";
    else if constexpr (std::is_same_v<T, GLint>)
        return "GLint";
    else if constexpr (std::is_same_v<T, GLuint>)
        return "GLuint";
    else if constexpr (std::is_same_v<T, GLshort>)
        return "GLshort";
    else if constexpr (std::is_same_v<T, GLushort>)
        return "GLushort";
    else if constexpr (std::is_same_v<T, GLbyte>)
        return "GLbyte";
    else
        return "GLubyte";  // also GLboolean, the same type
}

std::string floatingLiteral(double v, int digits, const char* suffix) {
    if (std::isnan(v)) return "NAN";
    if (std::isinf(v)) return v > 0 ? "INFINITY" : "-INFINITY";
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    std::string s = text;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s + suffix;
}

// How the unsigned-int parameters of a function print.
enum class UnsignedStyle { Enum, Number, ClearMask, PrimitiveMode };

template <class T>
std::string literal(T v, UnsignedStyle style) {
    if constexpr (std::is_same_v<T, GLfloat>) {
        return floatingLiteral(v, 9, "f");
    } else if constexpr (std::is_same_v<T, GLdouble>) {
        return floatingLiteral(v, 17, "");
    } else if constexpr (std::is_same_v<T, GLuint>) {
        std::string name = style == UnsignedStyle::ClearMask       ? clearMaskName(v)
                           : style == UnsignedStyle::PrimitiveMode ? primitiveModeName(v)
                           : style == UnsignedStyle::Enum          ? enumName(v)
                                                                   : std::string();
        if (!name.empty()) return name;
        char hex[16];
        std::snprintf(hex, sizeof hex, style == UnsignedStyle::Number ? "%uu" : "0x%X", v);
        return hex;
    } else {
        return std::to_string(v);
    }
}

// One parameter of an entry point: a value, the elements behind a const pointer, or the
// 16-element buffer a glGet*v writes into (answered back as a Get).
template <class T, std::size_t Count>
struct Parameter {
    static constexpr std::size_t kDoubles = 1;
    T value;
    explicit Parameter(ArgumentReader& r) : value(fromDouble<T>(r.take())) {}
    T get() { return value; }
    void answer(std::uint32_t, Answers&) const {}
    std::string declare(int) const { return {}; }
    std::string print(int, UnsignedStyle style) const { return literal(value, style); }
};

template <class T, std::size_t Count>
struct Parameter<const T*, Count> {
    static constexpr std::size_t kDoubles = Count;
    std::vector<T> data;
    explicit Parameter(ArgumentReader& r) {
        for (std::size_t i = 0; i < Count; ++i) data.push_back(fromDouble<T>(r.take()));
    }
    const T* get() { return data.data(); }
    void answer(std::uint32_t, Answers&) const {}
    std::string declare(int slot, UnsignedStyle style = UnsignedStyle::Number) const {
        std::string s = "const " + typeName<T>() + " a" + std::to_string(slot) + "[] = {";
        for (std::size_t i = 0; i < data.size(); ++i) s += (i ? ", " : "") + literal(data[i], style);
        return s + "}; ";
    }
    std::string print(int slot, UnsignedStyle) const { return "a" + std::to_string(slot); }
};

constexpr std::size_t kQueryElements = 16;  // the most any glGet*v of ours answers (a matrix)

template <class T, std::size_t Count>
struct Parameter<T*, Count> {
    static constexpr std::size_t kDoubles = 0;
    std::array<T, kQueryElements> data;
    explicit Parameter(ArgumentReader&) { std::memset(data.data(), 0xA5, sizeof data); }  // untouched slots show
    T* get() { return data.data(); }
    void answer(std::uint32_t index, Answers& answers) const {
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(data.data());
        answers.push_back({AnswerKind::Get, index, {bytes, bytes + sizeof data}});
    }
    std::string declare(int slot) const { return typeName<T>() + " out" + std::to_string(slot) + "[16]; "; }
    std::string print(int slot, UnsignedStyle) const { return "out" + std::to_string(slot); }
};

template <class R>
void answerReturn(R value, std::uint32_t index, Answers& answers) {
    if constexpr (std::is_pointer_v<R>) {  // glGetString: whether there is a string (their texts differ)
        answers.push_back({AnswerKind::Get, index, {static_cast<std::uint8_t>(value != nullptr)}});
    } else {
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
        // glGetError is the one entry point returning a GLenum.
        const AnswerKind kind = std::is_same_v<R, GLenum> ? AnswerKind::Error : AnswerKind::Get;
        answers.push_back({kind, index, {bytes, bytes + sizeof value}});
    }
}

using RunFunction = void (*)(const Call&, std::uint32_t, int, int, Answers&);
using PrintFunction = std::string (*)(const Call&);

struct FunctionInfo {
    std::string_view name;
    std::size_t argumentCount;
    RunFunction run;
    PrintFunction print;
};

UnsignedStyle unsignedStyle(std::string_view name) {
    if (name.starts_with("glColor")) return UnsignedStyle::Number;
    if (name == "glClear" || name.ends_with("Attrib")) return UnsignedStyle::ClearMask;
    if (name == "glBegin") return UnsignedStyle::PrimitiveMode;
    if (name.ends_with("List") || name.ends_with("Lists") || name == "glListBase") return UnsignedStyle::Number;
    if (name.ends_with("Texture") || name.ends_with("Textures") || name.starts_with("glStencil"))
        return UnsignedStyle::Number;
    return UnsignedStyle::Enum;
}

// The table entry for the glad slot `Slot`; `Count` elements lie behind each const pointer.
template <auto& Slot, std::size_t Count, class Signature = std::remove_reference_t<decltype(Slot)>>
struct Entry;

template <auto& Slot, std::size_t Count, class R, class... Args>
struct Entry<Slot, Count, R(GLAD_API_PTR*)(Args...)> {
    using Parameters = std::tuple<Parameter<Args, Count>...>;
    static constexpr std::size_t kDoubles = (std::size_t{0} + ... + Parameter<Args, Count>::kDoubles);

    static void run(const Call& call, std::uint32_t index, int, int, Answers& answers) {
        [[maybe_unused]] ArgumentReader reader{call.args};
        Parameters parameters{Parameter<Args, Count>(reader)...};  // braces: read left to right
        if constexpr (std::is_void_v<R>) {
            std::apply([](auto&... p) { Slot(p.get()...); }, parameters);
        } else {
            answerReturn(std::apply([](auto&... p) { return Slot(p.get()...); }, parameters), index, answers);
        }
        std::apply([&](const auto&... p) { (p.answer(index, answers), ...); }, parameters);
    }

    static std::string print(const Call& call, std::string_view name) {
        [[maybe_unused]] ArgumentReader reader{call.args};
        Parameters parameters{Parameter<Args, Count>(reader)...};
        const UnsignedStyle style = unsignedStyle(name);
        std::string declarations, arguments;
        int slot = 0;
        std::apply(
            [&](const auto&... p) {
                ((declarations += p.declare(slot), arguments += (slot ? ", " : "") + p.print(slot, style), ++slot),
                 ...);
            },
            parameters);
        const std::string statement = std::string(name) + "(" + arguments + ");";
        return declarations.empty() ? statement : "{ " + declarations + statement + " }";
    }
};

// Every entry point the fuzzer calls: state and drawing calls (with the elements it generates
// behind each pointer) and the queries.
// clang-format off
#define MYGL_DRAWING_CALLS(X)                                                                     \
    X(glad_glBegin, 0) X(glad_glEnd, 0)                                                          \
    X(glad_glVertex2d, 0) X(glad_glVertex2f, 0) X(glad_glVertex2i, 0) X(glad_glVertex2s, 0)      \
    X(glad_glVertex3d, 0) X(glad_glVertex3f, 0) X(glad_glVertex3i, 0) X(glad_glVertex3s, 0)      \
    X(glad_glVertex4d, 0) X(glad_glVertex4f, 0) X(glad_glVertex4i, 0) X(glad_glVertex4s, 0)      \
    X(glad_glVertex2dv, 2) X(glad_glVertex2fv, 2) X(glad_glVertex2iv, 2) X(glad_glVertex2sv, 2)  \
    X(glad_glVertex3dv, 3) X(glad_glVertex3fv, 3) X(glad_glVertex3iv, 3) X(glad_glVertex3sv, 3)  \
    X(glad_glVertex4dv, 4) X(glad_glVertex4fv, 4) X(glad_glVertex4iv, 4) X(glad_glVertex4sv, 4)  \
    X(glad_glColor3b, 0) X(glad_glColor3d, 0) X(glad_glColor3f, 0) X(glad_glColor3i, 0)          \
    X(glad_glColor3s, 0) X(glad_glColor3ub, 0) X(glad_glColor3ui, 0) X(glad_glColor3us, 0)       \
    X(glad_glColor4b, 0) X(glad_glColor4d, 0) X(glad_glColor4f, 0) X(glad_glColor4i, 0)          \
    X(glad_glColor4s, 0) X(glad_glColor4ub, 0) X(glad_glColor4ui, 0) X(glad_glColor4us, 0)       \
    X(glad_glColor3bv, 3) X(glad_glColor3dv, 3) X(glad_glColor3fv, 3) X(glad_glColor3iv, 3)      \
    X(glad_glColor3sv, 3) X(glad_glColor3ubv, 3) X(glad_glColor3uiv, 3) X(glad_glColor3usv, 3)   \
    X(glad_glColor4bv, 4) X(glad_glColor4dv, 4) X(glad_glColor4fv, 4) X(glad_glColor4iv, 4)      \
    X(glad_glColor4sv, 4) X(glad_glColor4ubv, 4) X(glad_glColor4uiv, 4) X(glad_glColor4usv, 4)   \
    X(glad_glNormal3b, 0) X(glad_glNormal3d, 0) X(glad_glNormal3f, 0) X(glad_glNormal3i, 0)      \
    X(glad_glNormal3s, 0) X(glad_glNormal3bv, 3) X(glad_glNormal3dv, 3) X(glad_glNormal3fv, 3)   \
    X(glad_glNormal3iv, 3) X(glad_glNormal3sv, 3)                                                 \
    X(glad_glTexCoord2d, 0) X(glad_glTexCoord2f, 0) X(glad_glTexCoord2i, 0) X(glad_glTexCoord2s, 0) \
    X(glad_glTexCoord2dv, 2) X(glad_glTexCoord2fv, 2) X(glad_glTexCoord2iv, 2) X(glad_glTexCoord2sv, 2) \
    X(glad_glEdgeFlag, 0) X(glad_glEdgeFlagv, 1)                                                  \
    X(glad_glRectd, 0) X(glad_glRectf, 0) X(glad_glRecti, 0) X(glad_glRects, 0)                  \
    X(glad_glRectdv, 2) X(glad_glRectfv, 2) X(glad_glRectiv, 2) X(glad_glRectsv, 2)              \
    X(glad_glMatrixMode, 0) X(glad_glLoadIdentity, 0) X(glad_glPushMatrix, 0) X(glad_glPopMatrix, 0) \
    X(glad_glLoadMatrixd, 16) X(glad_glLoadMatrixf, 16) X(glad_glMultMatrixd, 16) X(glad_glMultMatrixf, 16) \
    X(glad_glTranslated, 0) X(glad_glTranslatef, 0) X(glad_glRotated, 0) X(glad_glRotatef, 0)    \
    X(glad_glScaled, 0) X(glad_glScalef, 0) X(glad_glFrustum, 0) X(glad_glOrtho, 0)              \
    X(glad_glViewport, 0) X(glad_glDepthRange, 0)                                                 \
    X(glad_glEnable, 0) X(glad_glDisable, 0) X(glad_glCullFace, 0) X(glad_glFrontFace, 0)        \
    X(glad_glDepthFunc, 0) X(glad_glDepthMask, 0) X(glad_glShadeModel, 0) X(glad_glPolygonMode, 0) \
    X(glad_glLineWidth, 0) X(glad_glPointSize, 0) X(glad_glHint, 0) X(glad_glPixelStorei, 0)     \
    X(glad_glClearColor, 0) X(glad_glClearDepth, 0) X(glad_glClear, 0)                           \
    X(glad_glFlush, 0) X(glad_glFinish, 0)                                                       \
    X(glad_glPushAttrib, 0) X(glad_glPopAttrib, 0) X(glad_glPushClientAttrib, 0) X(glad_glPopClientAttrib, 0)
// clang-format on

// clang-format off
#define MYGL_QUERY_CALLS(X)                                                                       \
    X(glad_glGetError, 0) X(glad_glGetBooleanv, 0) X(glad_glGetIntegerv, 0) X(glad_glGetFloatv, 0) \
    X(glad_glGetDoublev, 0) X(glad_glIsEnabled, 0) X(glad_glGetString, 0)                        \
    X(glad_glGetLightfv, 0) X(glad_glGetLightiv, 0) X(glad_glGetMaterialfv, 0) X(glad_glGetMaterialiv, 0) \
    X(glad_glGetClipPlane, 0) X(glad_glIsList, 0)
// clang-format on

// Lighting, fog, polygon offset, clip planes and display lists: state calls the call recorder
// lists apart (their pointers hold up to 4 values for every parameter name).
// clang-format off
#define MYGL_FEATURE_CALLS(X)                                                                     \
    X(glad_glLightf, 0) X(glad_glLighti, 0) X(glad_glLightfv, 4) X(glad_glLightiv, 4)             \
    X(glad_glMaterialf, 0) X(glad_glMateriali, 0) X(glad_glMaterialfv, 4) X(glad_glMaterialiv, 4) \
    X(glad_glLightModelf, 0) X(glad_glLightModeli, 0) X(glad_glLightModelfv, 4) X(glad_glLightModeliv, 4) \
    X(glad_glColorMaterial, 0) X(glad_glFogf, 0) X(glad_glFogi, 0) X(glad_glFogfv, 4) X(glad_glFogiv, 4) \
    X(glad_glPolygonOffset, 0) X(glad_glClipPlane, 4)                                             \
    X(glad_glNewList, 0) X(glad_glEndList, 0) X(glad_glCallList, 0) X(glad_glDeleteLists, 0) X(glad_glListBase, 0)
// clang-format on

// Textures, per-fragment operations, stipple, pixel rectangles, raster positions and the
// accumulation buffer (the image calls are in image_calls.cpp). glGenTextures writes at most 16
// names, glPixelMap reads and glGetPixelMap writes at most 16 entries: the generator keeps to that.
// clang-format off
#define MYGL_PIXEL_FEATURE_CALLS(X)                                                               \
    X(glad_glGenTextures, 0) X(glad_glDeleteTextures, 4) X(glad_glBindTexture, 0) X(glad_glIsTexture, 0) \
    X(glad_glPrioritizeTextures, 4) X(glad_glTexParameterf, 0) X(glad_glTexParameteri, 0)        \
    X(glad_glTexParameterfv, 4) X(glad_glTexParameteriv, 4) X(glad_glTexEnvf, 0) X(glad_glTexEnvi, 0) \
    X(glad_glTexEnvfv, 4) X(glad_glTexEnviv, 4) X(glad_glTexGend, 0) X(glad_glTexGenf, 0) X(glad_glTexGeni, 0) \
    X(glad_glTexGendv, 4) X(glad_glTexGenfv, 4) X(glad_glTexGeniv, 4)                             \
    X(glad_glCopyTexImage1D, 0) X(glad_glCopyTexImage2D, 0) X(glad_glCopyTexSubImage1D, 0) X(glad_glCopyTexSubImage2D, 0) \
    X(glad_glGetTexParameterfv, 0) X(glad_glGetTexParameteriv, 0) X(glad_glGetTexLevelParameterfv, 0) \
    X(glad_glGetTexLevelParameteriv, 0) X(glad_glGetTexEnvfv, 0) X(glad_glGetTexEnviv, 0)        \
    X(glad_glGetTexGendv, 0) X(glad_glGetTexGenfv, 0) X(glad_glGetTexGeniv, 0)                    \
    X(glad_glTexCoord1d, 0) X(glad_glTexCoord1f, 0) X(glad_glTexCoord1i, 0) X(glad_glTexCoord1s, 0) \
    X(glad_glTexCoord3d, 0) X(glad_glTexCoord3f, 0) X(glad_glTexCoord3i, 0) X(glad_glTexCoord3s, 0) \
    X(glad_glTexCoord4d, 0) X(glad_glTexCoord4f, 0) X(glad_glTexCoord4i, 0) X(glad_glTexCoord4s, 0) \
    X(glad_glTexCoord1dv, 1) X(glad_glTexCoord1fv, 1) X(glad_glTexCoord1iv, 1) X(glad_glTexCoord1sv, 1) \
    X(glad_glTexCoord3dv, 3) X(glad_glTexCoord3fv, 3) X(glad_glTexCoord3iv, 3) X(glad_glTexCoord3sv, 3) \
    X(glad_glTexCoord4dv, 4) X(glad_glTexCoord4fv, 4) X(glad_glTexCoord4iv, 4) X(glad_glTexCoord4sv, 4) \
    X(glad_glScissor, 0) X(glad_glAlphaFunc, 0) X(glad_glStencilFunc, 0) X(glad_glStencilOp, 0)   \
    X(glad_glStencilMask, 0) X(glad_glClearStencil, 0) X(glad_glBlendFunc, 0) X(glad_glLogicOp, 0) \
    X(glad_glColorMask, 0) X(glad_glDrawBuffer, 0) X(glad_glReadBuffer, 0) X(glad_glLineStipple, 0) \
    X(glad_glCopyPixels, 0) X(glad_glPixelZoom, 0) X(glad_glPixelStoref, 0) X(glad_glPixelTransferf, 0) \
    X(glad_glPixelTransferi, 0) X(glad_glPixelMapfv, 16) X(glad_glPixelMapuiv, 16) X(glad_glPixelMapusv, 16) \
    X(glad_glGetPixelMapfv, 0) X(glad_glGetPixelMapuiv, 0) X(glad_glGetPixelMapusv, 0)            \
    X(glad_glRasterPos2d, 0) X(glad_glRasterPos2f, 0) X(glad_glRasterPos2i, 0) X(glad_glRasterPos2s, 0) \
    X(glad_glRasterPos3d, 0) X(glad_glRasterPos3f, 0) X(glad_glRasterPos3i, 0) X(glad_glRasterPos3s, 0) \
    X(glad_glRasterPos4d, 0) X(glad_glRasterPos4f, 0) X(glad_glRasterPos4i, 0) X(glad_glRasterPos4s, 0) \
    X(glad_glRasterPos2dv, 2) X(glad_glRasterPos2fv, 2) X(glad_glRasterPos2iv, 2) X(glad_glRasterPos2sv, 2) \
    X(glad_glRasterPos3dv, 3) X(glad_glRasterPos3fv, 3) X(glad_glRasterPos3iv, 3) X(glad_glRasterPos3sv, 3) \
    X(glad_glRasterPos4dv, 4) X(glad_glRasterPos4fv, 4) X(glad_glRasterPos4iv, 4) X(glad_glRasterPos4sv, 4) \
    X(glad_glClearAccum, 0) X(glad_glAccum, 0)
// clang-format on

const std::vector<FunctionInfo>& table() {
    static const std::vector<FunctionInfo> functions = [] {
        std::vector<FunctionInfo> t;
// clang-format off
#define MYGL_FUZZ_ENTRY(slot, count)                                                              \
    t.push_back({std::string_view(#slot).substr(5), Entry<slot, count>::kDoubles, &Entry<slot, count>::run, \
                 [](const Call& c) { return Entry<slot, count>::print(c, std::string_view(#slot).substr(5)); }});
        // clang-format on
        MYGL_DRAWING_CALLS(MYGL_FUZZ_ENTRY)
        MYGL_QUERY_CALLS(MYGL_FUZZ_ENTRY)
        MYGL_FEATURE_CALLS(MYGL_FUZZ_ENTRY)
        MYGL_PIXEL_FEATURE_CALLS(MYGL_FUZZ_ENTRY)
#undef MYGL_FUZZ_ENTRY
        for (const ImageFunction& f : imageFunctions()) t.push_back({f.name, f.argumentCount, f.run, f.print});
        return t;
    }();
    return functions;
}

}  // namespace

std::uint16_t functionId(std::string_view name) {
    static const auto ids = [] {
        std::unordered_map<std::string_view, std::uint16_t> map;
        for (std::size_t i = 0; i < table().size(); ++i) map.emplace(table()[i].name, static_cast<std::uint16_t>(i));
        return map;
    }();
    const auto found = ids.find(name);
    if (found == ids.end()) throw std::invalid_argument("the fuzzer has no GL function " + std::string(name));
    return found->second;
}

std::string_view functionName(const Call& call) { return table().at(call.function).name; }

std::size_t functionCount() { return table().size(); }

std::size_t argumentCount(std::uint16_t function) { return table().at(function).argumentCount; }

Call makeCall(std::string_view name, std::vector<double> args) {
    const std::uint16_t id = functionId(name);
    args.resize(argumentCount(id), 0.0);
    return {id, std::move(args)};
}

void runCall(const Call& call, std::uint32_t index, int width, int height, Answers& answers) {
    table().at(call.function).run(call, index, width, height, answers);
}

std::string toC(const Call& call) { return table().at(call.function).print(call); }

std::size_t readPixelsBytes(std::int64_t x, std::int64_t y, std::int64_t w, std::int64_t h, int bytesPerPixel,
                            int width, int height) {
    const std::int64_t lastColumn = std::min<std::int64_t>(x + w, width) - 1 - x;
    const std::int64_t lastRow = std::min<std::int64_t>(y + h, height) - 1 - y;
    if (w <= 0 || h <= 0 || lastColumn < std::max<std::int64_t>(0, -x) || lastRow < std::max<std::int64_t>(0, -y))
        return 4;
    const std::int64_t rowBytes = (w * bytesPerPixel + 7) / 8 * 8;
    return static_cast<std::size_t>(std::max<std::int64_t>(4, lastRow * rowBytes + (lastColumn + 1) * bytesPerPixel));
}

}  // namespace fuzz
