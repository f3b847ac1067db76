#pragma once
// The GLU helpers course programs use, computed in double above the dispatch and applied with
// glMultMatrixd through the loaded GL table, so every backend receives identical matrices.
#include <glad/gl.h>

namespace mygl {

void gluPerspective(GLdouble fovyDegrees, GLdouble aspect, GLdouble zNear, GLdouble zFar);
void gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY,
               GLdouble centerZ, GLdouble upX, GLdouble upY, GLdouble upZ);
void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);

}  // namespace mygl

// Course programs call these unqualified.
using mygl::gluLookAt;
using mygl::gluOrtho2D;
using mygl::gluPerspective;
