// Matrix modes and stacks. Double-precision entry points convert to float first, as the
// reference stores its matrices in float and builds them with its float arithmetic.
#include "compiled.h"

namespace mygl {
namespace {

// Runs `change` on the current matrix. It returns whether anything changed: the reference
// ends its vertex batch before a matrix call unless the call changes nothing it tracks.
template <class Change>
void changeMatrix(bool endsBatchAlways, Change&& change) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (endsBatchAlways) endBatch(*s);
    if (!change(s->currentStack().top())) return;
    if (!endsBatchAlways) endBatch(*s);
    s->modelviewProjectionStale = true;
    if (s->matrixMode == GL_PROJECTION) s->clipPlanesStale = true;
}

// The in-place and known-kind operations, which always count as a change.
template <class Operation>
void alwaysChange(Operation&& operation) {
    changeMatrix(true, [&](StackMatrix& top) {
        operation(top);
        return true;
    });
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
    if (s->matrixMode == GL_PROJECTION) s->clipPlanesStale = true;
}

template <class T>
void loadMatrix(const T* m) {
    if (m) changeMatrix(false, [&](StackMatrix& top) { return top.load(toMatrix(m)); });
}

template <class T>
void multMatrix(const T* m) {
    if (m) changeMatrix(false, [&](StackMatrix& top) { return top.multiply(toMatrix(m)); });
}

void rotate(float angle, float x, float y, float z) {
    alwaysChange([&](StackMatrix& top) { top.rotate(angle, x, y, z); });
}

void frustumOrOrtho(bool isFrustum, float l, float r, float b, float t, float n, float f) {
    Context::State* s = currentState();
    if (!s) return;
    // Checked after the conversion to float, as the reference does.
    const bool invalid =
        isFrustum ? (n <= 0.0f || f <= 0.0f || l == r || b == t || n == f) : (l == r || b == t || n == f);
    if (invalid && !s->insideBeginEnd) return setError(*s, GL_INVALID_VALUE);
    alwaysChange([&](StackMatrix& top) { isFrustum ? top.frustum(l, r, b, t, n, f) : top.ortho(l, r, b, t, n, f); });
}

float F(double v) { return static_cast<float>(v); }

const EntryPoint kEntryPoints[] = {
    listed<gl::glMatrixMode, +[](GLenum mode) { matrixMode(mode); }>(),
    listed<gl::glPushMatrix, +[] { pushMatrix(); }>(),
    listed<gl::glPopMatrix, +[] { popMatrix(); }>(),
    listed<gl::glLoadIdentity, +[] { alwaysChange([](StackMatrix& top) { top.loadIdentity(); }); }>(),
    listed<gl::glLoadMatrixf, +[](const GLfloat* m) { loadMatrix(m); }>(),
    listed<gl::glLoadMatrixd, +[](const GLdouble* m) { loadMatrix(m); }>(),
    listed<gl::glMultMatrixf, +[](const GLfloat* m) { multMatrix(m); }>(),
    listed<gl::glMultMatrixd, +[](const GLdouble* m) { multMatrix(m); }>(),
    listed<gl::glTranslatef,
           +[](GLfloat x, GLfloat y, GLfloat z) { alwaysChange([&](StackMatrix& top) { top.translate(x, y, z); }); }>(),
    listed<gl::glTranslated,
           +[](GLdouble x, GLdouble y, GLdouble z) {
               alwaysChange([&](StackMatrix& top) { top.translate(F(x), F(y), F(z)); });
           }>(),
    listed<gl::glScalef,
           +[](GLfloat x, GLfloat y, GLfloat z) { alwaysChange([&](StackMatrix& top) { top.scale(x, y, z); }); }>(),
    listed<gl::glScaled, +[](GLdouble x, GLdouble y,
                             GLdouble z) { alwaysChange([&](StackMatrix& top) { top.scale(F(x), F(y), F(z)); }); }>(),
    listed<gl::glRotatef, +[](GLfloat a, GLfloat x, GLfloat y, GLfloat z) { rotate(a, x, y, z); }>(),
    listed<gl::glRotated, +[](GLdouble a, GLdouble x, GLdouble y, GLdouble z) { rotate(F(a), F(x), F(y), F(z)); }>(),
    listed<gl::glFrustum, +[](GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n,
                              GLdouble f) { frustumOrOrtho(true, F(l), F(r), F(b), F(t), F(n), F(f)); }>(),
    listed<gl::glOrtho, +[](GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n,
                            GLdouble f) { frustumOrOrtho(false, F(l), F(r), F(b), F(t), F(n), F(f)); }>(),
};

}  // namespace

std::span<const EntryPoint> matrixEntryPoints() { return kEntryPoints; }

}  // namespace mygl
