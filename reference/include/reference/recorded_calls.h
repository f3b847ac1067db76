#pragma once
// The GL entry points that change state or draw, as an X-macro over glad's table slots: the call
// recorder wraps each of them, the differential fuzzer (tests/fuzz) generates calls to them.
// Requires <glad/gl.h>.

// Every recorded entry point, with the element count behind its pointer argument (0: none).
// clang-format off
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
    X(glad_glFlush, 0) X(glad_glFinish, 0)                                                       \
    X(glad_glPushAttrib, 0) X(glad_glPopAttrib, 0) X(glad_glPushClientAttrib, 0) X(glad_glPopClientAttrib, 0)
// clang-format on
