// gluProject, gluUnProject and gluUnProject4: object <-> window coordinates for given matrices
// and viewport, as GLU 1.3 defines them. They read no GL state.
#include <mygl/glu.h>

#include "matrix4.h"

using mygl::glu::invert;
using mygl::glu::multiply;
using mygl::glu::transform;

namespace {

// Window coordinates back to object coordinates through the inverse of proj * model.
bool unproject(const double window[4], const GLdouble* model, const GLdouble* proj, const GLint* view, double depthNear,
               double depthFar, double out[4]) {
    if (!model || !proj || !view || view[2] == 0 || view[3] == 0 || depthFar == depthNear) return false;
    double product[16], inverse[16];
    multiply(proj, model, product);
    if (!invert(product, inverse)) return false;
    const double ndc[4] = {(window[0] - view[0]) / view[2] * 2.0 - 1.0, (window[1] - view[1]) / view[3] * 2.0 - 1.0,
                           (window[2] - depthNear) / (depthFar - depthNear) * 2.0 - 1.0, window[3]};
    transform(inverse, ndc, out);
    return true;
}

}  // namespace

extern "C" {

GLint gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble* model, const GLdouble* proj,
                 const GLint* view, GLdouble* winX, GLdouble* winY, GLdouble* winZ) {
    if (!model || !proj || !view || !winX || !winY || !winZ) return GL_FALSE;
    const double object[4] = {objX, objY, objZ, 1.0};
    double eye[4], clip[4];
    transform(model, object, eye);
    transform(proj, eye, clip);
    if (clip[3] == 0.0) return GL_FALSE;
    for (int i = 0; i < 3; ++i) clip[i] = clip[i] / clip[3] * 0.5 + 0.5;
    *winX = view[0] + clip[0] * view[2];
    *winY = view[1] + clip[1] * view[3];
    *winZ = clip[2];
    return GL_TRUE;
}

GLint gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble* model, const GLdouble* proj,
                   const GLint* view, GLdouble* objX, GLdouble* objY, GLdouble* objZ) {
    const double window[4] = {winX, winY, winZ, 1.0};
    double object[4];
    if (!objX || !objY || !objZ || !unproject(window, model, proj, view, 0.0, 1.0, object)) return GL_FALSE;
    if (object[3] == 0.0) return GL_FALSE;
    *objX = object[0] / object[3];
    *objY = object[1] / object[3];
    *objZ = object[2] / object[3];
    return GL_TRUE;
}

GLint gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW, const GLdouble* model,
                    const GLdouble* proj, const GLint* view, GLdouble nearVal, GLdouble farVal, GLdouble* objX,
                    GLdouble* objY, GLdouble* objZ, GLdouble* objW) {
    const double window[4] = {winX, winY, winZ, clipW};
    double object[4];
    if (!objX || !objY || !objZ || !objW || !unproject(window, model, proj, view, nearVal, farVal, object)) {
        return GL_FALSE;
    }
    *objX = object[0];
    *objY = object[1];
    *objZ = object[2];
    *objW = object[3];
    return GL_TRUE;
}

}  // extern "C"
