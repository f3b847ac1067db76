// Matrix modes and stacks. Double-precision entry points convert to float first, as the
// reference stores its matrices in float.
#include <cmath>

#include "entry_points.h"

namespace mygl {
namespace {

// Runs `change` on the current matrix, then marks the combined matrix stale.
template <class Change>
void changeMatrix(Change&& change) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    endBatch(*s);
    change(*s, s->currentStack().top());
    s->modelviewProjectionStale = true;
}

void multiplyCurrent(const Matrix& m) {
    changeMatrix([&](Context::State&, Matrix& top) { top = multiply(top, m); });
}

template <class T>
Matrix toMatrix(const T* m) {
    Matrix out;
    for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<float>(m[i]);
    return out;
}

void matrixMode(GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) return setError(*s, GL_INVALID_ENUM);
    s->matrixMode = mode;
}

void pushMatrix() {
    Context::State* s = stateOutsideBeginEnd();
    if (s && !s->currentStack().push()) setError(*s, GL_STACK_OVERFLOW);
}

void popMatrix() {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    endBatch(*s);
    if (!s->currentStack().pop()) return setError(*s, GL_STACK_UNDERFLOW);
    s->modelviewProjectionStale = true;
}

template <class T>
void loadMatrix(const T* m) {
    if (m) changeMatrix([&](Context::State&, Matrix& top) { top = toMatrix(m); });
}

template <class T>
void multMatrix(const T* m) {
    if (m) multiplyCurrent(toMatrix(m));
}

void frustumOrOrtho(bool isFrustum, double l, double r, double b, double t, double n, double f) {
    Context::State* s = currentState();
    if (!s) return;
    const bool invalid = isFrustum ? (n <= 0.0 || f <= 0.0 || l == r || b == t || n == f) : (l == r || b == t || n == f);
    if (invalid && !s->insideBeginEnd) return setError(*s, GL_INVALID_VALUE);
    const auto F = [](double v) { return static_cast<float>(v); };
    multiplyCurrent(isFrustum ? frustum(F(l), F(r), F(b), F(t), F(n), F(f)) : ortho(F(l), F(r), F(b), F(t), F(n), F(f)));
}

const EntryPoint kEntryPoints[] = {
    {"glMatrixMode", entry(+[](GLenum mode) { matrixMode(mode); })},
    {"glPushMatrix", entry(+[] { pushMatrix(); })},
    {"glPopMatrix", entry(+[] { popMatrix(); })},
    {"glLoadIdentity", entry(+[] { changeMatrix([](Context::State&, Matrix& top) { top = kIdentity; }); })},
    {"glLoadMatrixf", entry(+[](const GLfloat* m) { loadMatrix(m); })},
    {"glLoadMatrixd", entry(+[](const GLdouble* m) { loadMatrix(m); })},
    {"glMultMatrixf", entry(+[](const GLfloat* m) { multMatrix(m); })},
    {"glMultMatrixd", entry(+[](const GLdouble* m) { multMatrix(m); })},
    {"glTranslatef", entry(+[](GLfloat x, GLfloat y, GLfloat z) { multiplyCurrent(translation(x, y, z)); })},
    {"glTranslated", entry(+[](GLdouble x, GLdouble y, GLdouble z) {
         multiplyCurrent(translation(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)));
     })},
    {"glScalef", entry(+[](GLfloat x, GLfloat y, GLfloat z) { multiplyCurrent(scaling(x, y, z)); })},
    {"glScaled", entry(+[](GLdouble x, GLdouble y, GLdouble z) {
         multiplyCurrent(scaling(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)));
     })},
    {"glRotatef", entry(+[](GLfloat a, GLfloat x, GLfloat y, GLfloat z) { multiplyCurrent(rotation(a, x, y, z)); })},
    {"glRotated", entry(+[](GLdouble a, GLdouble x, GLdouble y, GLdouble z) {
         multiplyCurrent(rotation(static_cast<float>(a), static_cast<float>(x), static_cast<float>(y),
                                  static_cast<float>(z)));
     })},
    {"glFrustum", entry(+[](GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
         frustumOrOrtho(true, l, r, b, t, n, f);
     })},
    {"glOrtho", entry(+[](GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
         frustumOrOrtho(false, l, r, b, t, n, f);
     })},
};

}  // namespace

std::span<const EntryPoint> matrixEntryPoints() { return kEntryPoints; }

}  // namespace mygl
