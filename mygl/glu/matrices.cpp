// GLU's matrix helpers, computed in double and applied through the loaded GL table, so the same
// matrices reach whichever backend is current.
#include <mygl/glu.h>

#include <cmath>

namespace {

void normalize(double v[3]) {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (length == 0.0) return;
    for (int i = 0; i < 3; ++i) v[i] /= length;
}

void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

extern "C" {

void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) {
    const double radians = fovy / 2.0 * M_PI / 180.0;
    const double deltaZ = zFar - zNear;
    const double sine = std::sin(radians);
    if (deltaZ == 0.0 || sine == 0.0 || aspect == 0.0) return;  // as GLU: no change
    const double cotangent = std::cos(radians) / sine;
    const GLdouble m[16] = {
        cotangent / aspect,           0, 0, 0, 0, cotangent, 0, 0, 0, 0, -(zFar + zNear) / deltaZ, -1, 0, 0,
        -2.0 * zNear * zFar / deltaZ, 0};
    glMultMatrixd(m);
}

void gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY, GLdouble centerZ,
               GLdouble upX, GLdouble upY, GLdouble upZ) {
    double forward[3] = {centerX - eyeX, centerY - eyeY, centerZ - eyeZ};
    const double up[3] = {upX, upY, upZ};
    normalize(forward);
    double side[3], trueUp[3];
    cross(forward, up, side);
    normalize(side);
    cross(side, forward, trueUp);
    const GLdouble m[16] = {side[0], trueUp[0], -forward[0], 0, side[1], trueUp[1], -forward[1], 0,
                            side[2], trueUp[2], -forward[2], 0, 0,       0,         0,           1};
    glMultMatrixd(m);
    glTranslated(-eyeX, -eyeY, -eyeZ);
}

void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top) {
    glOrtho(left, right, bottom, top, -1.0, 1.0);
}

// Maps the region of delX x delY pixels centred on (x, y) of the viewport to the whole clip volume.
void gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint* viewport) {
    if (!viewport || delX <= 0.0 || delY <= 0.0) return;  // as GLU: no change
    glTranslated((viewport[2] - 2.0 * (x - viewport[0])) / delX, (viewport[3] - 2.0 * (y - viewport[1])) / delY, 0.0);
    glScaled(viewport[2] / delX, viewport[3] / delY, 1.0);
}

}  // extern "C"
