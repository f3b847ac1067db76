#include "reference/call_recorder.h"

#include <glad/gl.h>

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

// How many elements a pointer argument of the call points at: a number, or a function of the
// call's arguments.
template <auto Count, class... Args>
std::size_t elementCount(Args... args) {
    if constexpr (std::is_invocable_v<decltype(Count), Args...>) return Count(args...);
    else return Count;
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

// Every recorded entry point, with the element count behind its pointer argument (0: none).
#define MYGL_RECORDED_CALLS(X)                                                                    \
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
    X(glad_glFlush, 0) X(glad_glFinish, 0)                                                        \
    X(glad_glRasterPos2d, 0) X(glad_glRasterPos2f, 0) X(glad_glRasterPos2i, 0) X(glad_glRasterPos2s, 0) \
    X(glad_glRasterPos3d, 0) X(glad_glRasterPos3f, 0) X(glad_glRasterPos3i, 0) X(glad_glRasterPos3s, 0) \
    X(glad_glRasterPos4d, 0) X(glad_glRasterPos4f, 0) X(glad_glRasterPos4i, 0) X(glad_glRasterPos4s, 0) \
    X(glad_glRasterPos2dv, 2) X(glad_glRasterPos2fv, 2) X(glad_glRasterPos2iv, 2) X(glad_glRasterPos2sv, 2) \
    X(glad_glRasterPos3dv, 3) X(glad_glRasterPos3fv, 3) X(glad_glRasterPos3iv, 3) X(glad_glRasterPos3sv, 3) \
    X(glad_glRasterPos4dv, 4) X(glad_glRasterPos4fv, 4) X(glad_glRasterPos4iv, 4) X(glad_glRasterPos4sv, 4) \
    X(glad_glBitmap, bitmapBytes)

void installAll() {
#define MYGL_INSTALL(slot, count) Wrapper<slot, count>::install();
    MYGL_RECORDED_CALLS(MYGL_INSTALL)
#undef MYGL_INSTALL
}

void uninstallAll() {
#define MYGL_UNINSTALL(slot, count) Wrapper<slot, count>::uninstall();
    MYGL_RECORDED_CALLS(MYGL_UNINSTALL)
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
