#include "reference/call_recorder.h"
#include "reference/recorded_calls.h"

#include <glad/gl.h>

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

namespace reference {
namespace {

CallRecorder* active = nullptr;

// An argument kept for replay: values as they are, and for a pointer to const data the `count`
// elements behind it (the pointer the program passed may not outlive the call).
template <class T>
struct Kept {
    T value;
    Kept(T v, std::size_t) : value(v) {}
    T get() const { return value; }
};
template <class T>
struct Kept<const T*> {
    std::vector<T> data;
    bool null;
    Kept(const T* p, std::size_t count) : data(p ? std::vector<T>(p, p + count) : std::vector<T>()), null(!p) {}
    const T* get() const { return null ? nullptr : data.data(); }
};

// Untyped data: the `count` bytes behind it are copied; with a count of 0 the pointer itself is
// kept (vertex array pointers, which glDrawArrays reads when the call is replayed).
template <>
struct Kept<const void*> {
    std::vector<unsigned char> data;
    const void* pointer;
    Kept(const void* p, std::size_t bytes)
        : data(p && bytes ? std::vector<unsigned char>(static_cast<const unsigned char*>(p),
                                                       static_cast<const unsigned char*>(p) + bytes)
                          : std::vector<unsigned char>()),
          pointer(p) {}
    const void* get() const { return data.empty() ? pointer : data.data(); }
};

// Words the call writes. With a count (glGenTextures' names) the replay writes storage of its
// own, as the program's array may be gone by then (the backend generates the same names again);
// without one (glSelectBuffer's hit buffer) the program's pointer is kept.
template <>
struct Kept<GLuint*> {
    GLuint* pointer;
    mutable std::vector<GLuint> names;
    Kept(GLuint* p, std::size_t count) : pointer(p), names(count) {}
    GLuint* get() const { return names.empty() ? pointer : names.data(); }
};

// How many elements a pointer argument of the call points at: a number, or a function of the
// call's arguments.
template <auto Count, class... Args>
std::size_t elementCount(Args... args) {
    if constexpr (std::is_invocable_v<decltype(Count), Args...>)
        return Count(args...);
    else
        return Count;
}

// The wrapper for the table entry `Slot`: records the call, then forwards it to the backend
// the table pointed at when recording started. `Count` says how many elements a pointer
// argument points at (elementCount). Replay calls through `Slot`, i.e. through whatever table
// is loaded then.
template <auto& Slot, auto Count, class Signature = std::remove_reference_t<decltype(Slot)>>
struct Wrapper;

template <auto& Slot, auto Count, class R, class... Args>
struct Wrapper<Slot, Count, R(GLAD_API_PTR*)(Args...)> {
    static inline R(GLAD_API_PTR* original)(Args...) = nullptr;

    static R GLAD_API_PTR call(Args... args) {
        if (active) {
            [[maybe_unused]] const std::size_t count = elementCount<Count>(args...);
            active->add([kept = std::make_tuple(Kept<Args>(args, count)...)] {
                std::apply([](const auto&... k) { Slot(k.get()...); }, kept);
            });
        }
        return original(args...);
    }
    static void install() {
        original = Slot;
        if (original) Slot = &call;
    }
    static void uninstall() {
        if (original) Slot = original;
    }
};

// glBitmap's bytes depend on its size and the unpack alignment in force (asked of the backend:
// a query, not recorded).
std::size_t bitmapBytes(GLsizei width, GLsizei height, GLfloat, GLfloat, GLfloat, GLfloat, const GLubyte*) {
    if (width <= 0 || height <= 0) return 0;
    GLint alignment = 4;
    if (glad_glGetIntegerv) glad_glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    const std::size_t a = alignment > 0 ? static_cast<std::size_t>(alignment) : 1;
    return ((static_cast<std::size_t>(width) + 7) / 8 + a - 1) / a * a * static_cast<std::size_t>(height);
}

// Bytes glPolygonStipple reads: 32 rows of 32 bits under the unpack modes.
std::size_t polygonStippleBytes(const GLubyte*) {
    if (!glad_glGetIntegerv) return 0;
    GLint alignment = 4, rowLength = 0, skipPixels = 0, skipRows = 0;
    glad_glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glad_glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    glad_glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
    glad_glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
    const std::size_t a = alignment > 0 ? static_cast<std::size_t>(alignment) : 1;
    const std::size_t rowBits = rowLength > 0 ? static_cast<std::size_t>(rowLength) : 32;
    const std::size_t stride = (rowBits + 8 * a - 1) / (8 * a) * a;
    const std::size_t firstBit = static_cast<std::size_t>(std::max(skipPixels, 0));
    return (static_cast<std::size_t>(std::max(skipRows, 0)) + 31) * stride + (firstBit + 32 + 7) / 8;
}

// Bytes of glCallLists' names and glDrawElements' indices.
std::size_t bytesOf(GLenum type, GLsizei n) {
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
std::size_t callListsBytes(GLsizei n, GLenum type, const void*) { return bytesOf(type, n); }
std::size_t elementBytes(GLenum, GLsizei count, GLenum type, const void*) { return bytesOf(type, count); }

// Values behind the pointer of glLight*v, glMaterial*v and glLightModel*v: 4 for colours and
// positions, 3 for the spot direction and the colour indexes, 1 otherwise.
std::size_t lightParameterCount(GLenum name) {
    const bool four = name == GL_AMBIENT || name == GL_DIFFUSE || name == GL_SPECULAR || name == GL_POSITION ||
                      name == GL_EMISSION || name == GL_AMBIENT_AND_DIFFUSE || name == GL_LIGHT_MODEL_AMBIENT;
    return four ? 4 : name == GL_SPOT_DIRECTION || name == GL_COLOR_INDEXES ? 3 : 1;
}
template <class T>
std::size_t lightCount(GLenum, GLenum name, const T*) {
    return lightParameterCount(name);
}
template <class T>
std::size_t lightModelCount(GLenum name, const T*) {
    return lightParameterCount(name);
}
// Bytes of a client image of width x height x depth pixels under the unpack state in force
// (asked of the backend: queries, not recorded), from the pointer to the last byte read.
std::size_t imageBytes(GLsizei width, GLsizei height, GLenum format, GLenum type) {
    if (width <= 0 || height <= 0 || !glad_glGetIntegerv) return 0;
    GLint alignment = 4, rowLength = 0, skipPixels = 0, skipRows = 0;
    glad_glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glad_glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    glad_glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
    glad_glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
    const std::size_t components = format == GL_RGBA || format == 0x80E1 /* GL_BGRA */ ? 4
                                   : format == GL_RGB || format == 0x80E0 /* GL_BGR */ ? 3
                                   : format == GL_LUMINANCE_ALPHA                      ? 2
                                                                                       : 1;
    const std::size_t component = type == GL_UNSIGNED_BYTE || type == GL_BYTE     ? 1
                                  : type == GL_UNSIGNED_SHORT || type == GL_SHORT ? 2
                                                                                  : 4;
    const std::size_t pixel = components * component;
    const std::size_t rowPixels = static_cast<std::size_t>(rowLength > 0 ? rowLength : width);
    const std::size_t a = alignment > 0 ? static_cast<std::size_t>(alignment) : 1;
    if (type == GL_BITMAP) {  // rows of bits padded to the alignment; skipped pixels are bits
        const std::size_t rowBytes = (rowPixels + 8 * a - 1) / (8 * a) * a;
        const std::size_t skipBits = static_cast<std::size_t>(std::max(skipPixels, 0));
        return static_cast<std::size_t>(std::max(skipRows, 0)) * rowBytes + skipBits / 8 +
               static_cast<std::size_t>(height - 1) * rowBytes +
               (skipBits % 8 + static_cast<std::size_t>(width) + 7) / 8;
    }
    std::size_t stride = rowPixels * pixel;
    if (component < a) stride = (stride + a - 1) / a * a;
    const std::size_t first = static_cast<std::size_t>(std::max(skipRows, 0)) * stride +
                              static_cast<std::size_t>(std::max(skipPixels, 0)) * pixel;
    return first + static_cast<std::size_t>(height - 1) * stride + static_cast<std::size_t>(width) * pixel;
}
std::size_t texImage1DBytes(GLenum, GLint, GLint, GLsizei w, GLint, GLenum format, GLenum type, const void*) {
    return imageBytes(w, 1, format, type);
}
std::size_t texImage2DBytes(GLenum, GLint, GLint, GLsizei w, GLsizei h, GLint, GLenum format, GLenum type,
                            const void*) {
    return imageBytes(w, h, format, type);
}
std::size_t texSubImage1DBytes(GLenum, GLint, GLint, GLsizei w, GLenum format, GLenum type, const void*) {
    return imageBytes(w, 1, format, type);
}
std::size_t texSubImage2DBytes(GLenum, GLint, GLint, GLint, GLsizei w, GLsizei h, GLenum format, GLenum type,
                               const void*) {
    return imageBytes(w, h, format, type);
}
std::size_t drawPixelsBytes(GLsizei w, GLsizei h, GLenum format, GLenum type, const void*) {
    return imageBytes(w, h, format, type);
}
template <class T>
std::size_t pixelMapCount(GLenum, GLsizei n, const T*) {
    return n > 0 ? static_cast<std::size_t>(n) : 0;
}
std::size_t namesCount(GLsizei n, const GLuint*) { return n > 0 ? static_cast<std::size_t>(n) : 0; }
std::size_t generatedCount(GLsizei n, GLuint*) { return n > 0 ? static_cast<std::size_t>(n) : 0; }
std::size_t priorityCount(GLsizei n, const GLuint*, const GLclampf*) { return n > 0 ? static_cast<std::size_t>(n) : 0; }
// Values behind glTexParameter*v, glTexEnv*v and glTexGen*v: 4 for colours and planes.
template <class T>
std::size_t textureParameterCount(GLenum, GLenum name, const T*) {
    return name == GL_TEXTURE_BORDER_COLOR || name == GL_TEXTURE_ENV_COLOR || name == GL_OBJECT_PLANE ||
                   name == GL_EYE_PLANE
               ? 4
               : 1;
}

// Values behind the pointer of glFog*v: 4 for the colour, 1 otherwise.
template <class T>
std::size_t fogCount(GLenum name, const T*) {
    return name == GL_FOG_COLOR ? 4 : 1;
}

// Values behind glMap1's and glMap2's pointers: the last point's offset plus its components
// (1 for arguments the call rejects).
std::size_t mapComponents(GLenum target) {
    const GLenum first = target >= GL_MAP2_COLOR_4 ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4;
    if (target < first || target > first + 8) return 0;
    constexpr std::size_t kComponents[] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
    return kComponents[target - first];
}
std::size_t mapPoints(GLenum target, GLint ustride, GLint uorder, GLint vstride, GLint vorder) {
    const std::size_t size = mapComponents(target);
    if (size == 0 || uorder < 1 || uorder > 30 || vorder < 1 || vorder > 30 || ustride < GLint(size) ||
        vstride < GLint(size)) {
        return 1;
    }
    return std::size_t(uorder - 1) * std::size_t(ustride) + std::size_t(vorder - 1) * std::size_t(vstride) + size;
}
template <class T>
std::size_t map1Count(GLenum target, T, T, GLint stride, GLint order, const T*) {
    return mapPoints(target, stride, order, stride, 1);
}
template <class T>
std::size_t map2Count(GLenum target, T, T, GLint ustride, GLint uorder, T, T, GLint vstride, GLint vorder, const T*) {
    return mapPoints(target, ustride, uorder, vstride, vorder);
}

// Recorded besides the shared list (recorded_calls.h): raster positions and bitmaps, display
// lists, lighting, fog, polygon offset, stipple, the per-fragment operations, textures, pixel rectangles, accumulation,
// colour index, buffer selection, selection and feedback (the program's hit or feedback buffer is written again by the
// replay), and vertex arrays (their pointers are kept, so the arrays are read when the frame is replayed: the program's
// arrays must still hold the frame's data then, as static arrays do).
// clang-format off
#define MYGL_FURTHER_CALLS(X)                                                                      \
    X(glad_glRasterPos2d, 0) X(glad_glRasterPos2f, 0) X(glad_glRasterPos2i, 0) X(glad_glRasterPos2s, 0) \
    X(glad_glRasterPos3d, 0) X(glad_glRasterPos3f, 0) X(glad_glRasterPos3i, 0) X(glad_glRasterPos3s, 0) \
    X(glad_glRasterPos4d, 0) X(glad_glRasterPos4f, 0) X(glad_glRasterPos4i, 0) X(glad_glRasterPos4s, 0) \
    X(glad_glRasterPos2dv, 2) X(glad_glRasterPos2fv, 2) X(glad_glRasterPos2iv, 2) X(glad_glRasterPos2sv, 2) \
    X(glad_glRasterPos3dv, 3) X(glad_glRasterPos3fv, 3) X(glad_glRasterPos3iv, 3) X(glad_glRasterPos3sv, 3) \
    X(glad_glRasterPos4dv, 4) X(glad_glRasterPos4fv, 4) X(glad_glRasterPos4iv, 4) X(glad_glRasterPos4sv, 4) \
    X(glad_glBitmap, bitmapBytes)                                                                  \
    X(glad_glNewList, 0) X(glad_glEndList, 0) X(glad_glCallList, 0) X(glad_glCallLists, callListsBytes) \
    X(glad_glGenLists, 0) X(glad_glDeleteLists, 0) X(glad_glListBase, 0)                          \
    X(glad_glVertexPointer, 0) X(glad_glColorPointer, 0) X(glad_glNormalPointer, 0)              \
    X(glad_glTexCoordPointer, 0) X(glad_glEdgeFlagPointer, 0) X(glad_glIndexPointer, 0)          \
    X(glad_glInterleavedArrays, 0) X(glad_glEnableClientState, 0) X(glad_glDisableClientState, 0) \
    X(glad_glArrayElement, 0) X(glad_glDrawArrays, 0) X(glad_glDrawElements, elementBytes)         \
    X(glad_glLightf, 0) X(glad_glLighti, 0) X(glad_glLightfv, lightCount<GLfloat>) X(glad_glLightiv, lightCount<GLint>) \
    X(glad_glMaterialf, 0) X(glad_glMateriali, 0) X(glad_glMaterialfv, lightCount<GLfloat>)      \
    X(glad_glMaterialiv, lightCount<GLint>) X(glad_glLightModelf, 0) X(glad_glLightModeli, 0)    \
    X(glad_glLightModelfv, lightModelCount<GLfloat>) X(glad_glLightModeliv, lightModelCount<GLint>) \
    X(glad_glColorMaterial, 0) \
    X(glad_glFogf, 0) X(glad_glFogi, 0) X(glad_glFogfv, fogCount<GLfloat>) X(glad_glFogiv, fogCount<GLint>) \
    X(glad_glPolygonOffset, 0) X(glad_glLineStipple, 0) X(glad_glPolygonStipple, polygonStippleBytes) \
    X(glad_glScissor, 0) X(glad_glAlphaFunc, 0) X(glad_glStencilFunc, 0) X(glad_glStencilOp, 0)             \
    X(glad_glStencilMask, 0) X(glad_glClearStencil, 0) X(glad_glBlendFunc, 0) X(glad_glLogicOp, 0)           \
    X(glad_glColorMask, 0) \
    X(glad_glGenTextures, generatedCount) X(glad_glBindTexture, 0) X(glad_glDeleteTextures, namesCount)       \
    X(glad_glPrioritizeTextures, priorityCount) X(glad_glTexImage1D, texImage1DBytes)                        \
    X(glad_glTexImage2D, texImage2DBytes) X(glad_glTexSubImage1D, texSubImage1DBytes)                        \
    X(glad_glTexSubImage2D, texSubImage2DBytes) X(glad_glCopyTexImage1D, 0) X(glad_glCopyTexImage2D, 0)      \
    X(glad_glCopyTexSubImage1D, 0) X(glad_glCopyTexSubImage2D, 0) X(glad_glTexParameterf, 0)                 \
    X(glad_glTexParameteri, 0) X(glad_glTexParameterfv, textureParameterCount<GLfloat>)                      \
    X(glad_glTexParameteriv, textureParameterCount<GLint>) X(glad_glTexEnvf, 0) X(glad_glTexEnvi, 0)          \
    X(glad_glTexEnvfv, textureParameterCount<GLfloat>) X(glad_glTexEnviv, textureParameterCount<GLint>)      \
    X(glad_glTexCoord1d, 0) X(glad_glTexCoord1f, 0) X(glad_glTexCoord1i, 0) X(glad_glTexCoord1s, 0)          \
    X(glad_glTexCoord3d, 0) X(glad_glTexCoord3f, 0) X(glad_glTexCoord3i, 0) X(glad_glTexCoord3s, 0)          \
    X(glad_glTexCoord4d, 0) X(glad_glTexCoord4f, 0) X(glad_glTexCoord4i, 0) X(glad_glTexCoord4s, 0)          \
    X(glad_glTexCoord1dv, 1) X(glad_glTexCoord1fv, 1) X(glad_glTexCoord1iv, 1) X(glad_glTexCoord1sv, 1)      \
    X(glad_glTexCoord3dv, 3) X(glad_glTexCoord3fv, 3) X(glad_glTexCoord3iv, 3) X(glad_glTexCoord3sv, 3)      \
    X(glad_glTexCoord4dv, 4) X(glad_glTexCoord4fv, 4) X(glad_glTexCoord4iv, 4) X(glad_glTexCoord4sv, 4)      \
    X(glad_glTexGend, 0) X(glad_glTexGenf, 0) X(glad_glTexGeni, 0) X(glad_glTexGendv, textureParameterCount<GLdouble>) \
    X(glad_glTexGenfv, textureParameterCount<GLfloat>) X(glad_glTexGeniv, textureParameterCount<GLint>)       \
    X(glad_glPixelStoref, 0) \
    X(glad_glDrawPixels, drawPixelsBytes) X(glad_glCopyPixels, 0) X(glad_glPixelZoom, 0) \
    X(glad_glPixelTransferf, 0) X(glad_glPixelTransferi, 0) X(glad_glPixelMapfv, pixelMapCount<GLfloat>) \
    X(glad_glPixelMapuiv, pixelMapCount<GLuint>) X(glad_glPixelMapusv, pixelMapCount<GLushort>) \
    X(glad_glRenderMode, 0) X(glad_glSelectBuffer, 0) X(glad_glInitNames, 0) X(glad_glLoadName, 0)          \
    X(glad_glPushName, 0) X(glad_glPopName, 0) X(glad_glClipPlane, 4) \
    X(glad_glMap1f, map1Count<GLfloat>) X(glad_glMap1d, map1Count<GLdouble>) X(glad_glMap2f, map2Count<GLfloat>) \
    X(glad_glMap2d, map2Count<GLdouble>) X(glad_glMapGrid1f, 0) X(glad_glMapGrid1d, 0) X(glad_glMapGrid2f, 0)    \
    X(glad_glMapGrid2d, 0) X(glad_glEvalCoord1f, 0) X(glad_glEvalCoord1d, 0) X(glad_glEvalCoord1fv, 1)          \
    X(glad_glEvalCoord1dv, 1) X(glad_glEvalCoord2f, 0) X(glad_glEvalCoord2d, 0) X(glad_glEvalCoord2fv, 2)      \
    X(glad_glEvalCoord2dv, 2) X(glad_glEvalPoint1, 0) X(glad_glEvalPoint2, 0) X(glad_glEvalMesh1, 0)           \
    X(glad_glEvalMesh2, 0) \
    X(glad_glClearAccum, 0) X(glad_glAccum, 0) X(glad_glDrawBuffer, 0) X(glad_glReadBuffer, 0)              \
    X(glad_glIndexd, 0) X(glad_glIndexf, 0) X(glad_glIndexi, 0) X(glad_glIndexs, 0) X(glad_glIndexub, 0)   \
    X(glad_glIndexdv, 1) X(glad_glIndexfv, 1) X(glad_glIndexiv, 1) X(glad_glIndexsv, 1) X(glad_glIndexubv, 1) \
    X(glad_glClearIndex, 0) X(glad_glIndexMask, 0) X(glad_glFeedbackBuffer, 0) X(glad_glPassThrough, 0)
// clang-format on

void installAll() {
#define MYGL_INSTALL(slot, count) Wrapper<slot, count>::install();
    MYGL_RECORDED_CALLS(MYGL_INSTALL)
    MYGL_FURTHER_CALLS(MYGL_INSTALL)
#undef MYGL_INSTALL
}

void uninstallAll() {
#define MYGL_UNINSTALL(slot, count) Wrapper<slot, count>::uninstall();
    MYGL_RECORDED_CALLS(MYGL_UNINSTALL)
    MYGL_FURTHER_CALLS(MYGL_UNINSTALL)
#undef MYGL_UNINSTALL
}

}  // namespace

CallRecorder::~CallRecorder() { stop(); }

void CallRecorder::start() {
    if (recording_) return;
    if (active) throw std::logic_error("another CallRecorder is recording");
    active = this;
    recording_ = true;
    installAll();
}

void CallRecorder::stop() {
    if (!recording_) return;
    uninstallAll();
    active = nullptr;
    recording_ = false;
}

void CallRecorder::replay() const {
    if (recording_) throw std::logic_error("stop recording before replaying");
    for (const auto& call : calls_) call();
}

}  // namespace reference
