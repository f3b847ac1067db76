#pragma once
// The one list of OpenGL 1.1's functions (1.0 and 1.1, compatibility profile): the 336 names glad
// generates for `--api gl:compatibility=1.1`, in alphabetical order, each once, with
// - its display-list class (GL 1.1 spec, section 5.4):
//   compiled      kept in a list being compiled, with its arguments and a copy of the data behind
//                 its pointer arguments (`count` elements);
//   dereferenced  kept in a list, with the data it reads from client memory dereferenced when it
//                 is compiled: client images unpacked under the pixel store of that moment
//                 (glBitmap, glDrawPixels, glTexImage, glPolygonStipple), vertex arrays read
//                 (glArrayElement, glDrawArrays, glDrawElements);
//   immediate     executed at once, never compiled (section 5.4's list, and glNewList/glEndList);
//   query         returns state and changes none (the Get and Is commands, glReadPixels, ...):
//                 not compiled either (section 5.4), and not recorded;
// - the count rule of its pointer argument: a number of elements, or a rule of count_rules.h
//   (a function of the call's arguments, and of the unpack modes for client images).
// MYGL_GL11_CALLS(X) expands X(name, class, count) once per function. It drives MyGL's entry
// points (the stubs of what is not implemented, the display-list wrappers: mygl/src/compiled.h)
// and the reference's CallRecorder. glcalls::call::NAME holds one function's entry (its `count` names a rule
// of namespace glcalls: use kCount outside it).
// Requires <glad/gl.h>: NAME there is glad's macro for its table slot glad_NAME.
#include <glad/gl.h>

#include "glcalls/count_rules.h"

// clang-format off
#define MYGL_GL11_CALLS(X) \
    X(glAccum, compiled, 0) \
    X(glAlphaFunc, compiled, 0) \
    X(glAreTexturesResident, query, 0) \
    X(glArrayElement, dereferenced, 0) \
    X(glBegin, compiled, 0) \
    X(glBindTexture, compiled, 0) \
    X(glBitmap, dereferenced, bitmapBytes) \
    X(glBlendFunc, compiled, 0) \
    X(glCallList, compiled, 0) \
    X(glCallLists, compiled, callListsBytes) \
    X(glClear, compiled, 0) \
    X(glClearAccum, compiled, 0) \
    X(glClearColor, compiled, 0) \
    X(glClearDepth, compiled, 0) \
    X(glClearIndex, compiled, 0) \
    X(glClearStencil, compiled, 0) \
    X(glClipPlane, compiled, 4) \
    X(glColor3b, compiled, 0) \
    X(glColor3bv, compiled, 3) \
    X(glColor3d, compiled, 0) \
    X(glColor3dv, compiled, 3) \
    X(glColor3f, compiled, 0) \
    X(glColor3fv, compiled, 3) \
    X(glColor3i, compiled, 0) \
    X(glColor3iv, compiled, 3) \
    X(glColor3s, compiled, 0) \
    X(glColor3sv, compiled, 3) \
    X(glColor3ub, compiled, 0) \
    X(glColor3ubv, compiled, 3) \
    X(glColor3ui, compiled, 0) \
    X(glColor3uiv, compiled, 3) \
    X(glColor3us, compiled, 0) \
    X(glColor3usv, compiled, 3) \
    X(glColor4b, compiled, 0) \
    X(glColor4bv, compiled, 4) \
    X(glColor4d, compiled, 0) \
    X(glColor4dv, compiled, 4) \
    X(glColor4f, compiled, 0) \
    X(glColor4fv, compiled, 4) \
    X(glColor4i, compiled, 0) \
    X(glColor4iv, compiled, 4) \
    X(glColor4s, compiled, 0) \
    X(glColor4sv, compiled, 4) \
    X(glColor4ub, compiled, 0) \
    X(glColor4ubv, compiled, 4) \
    X(glColor4ui, compiled, 0) \
    X(glColor4uiv, compiled, 4) \
    X(glColor4us, compiled, 0) \
    X(glColor4usv, compiled, 4) \
    X(glColorMask, compiled, 0) \
    X(glColorMaterial, compiled, 0) \
    X(glColorPointer, immediate, 0) \
    X(glCopyPixels, compiled, 0) \
    X(glCopyTexImage1D, compiled, 0) \
    X(glCopyTexImage2D, compiled, 0) \
    X(glCopyTexSubImage1D, compiled, 0) \
    X(glCopyTexSubImage2D, compiled, 0) \
    X(glCullFace, compiled, 0) \
    X(glDeleteLists, immediate, 0) \
    X(glDeleteTextures, immediate, namesCount) \
    X(glDepthFunc, compiled, 0) \
    X(glDepthMask, compiled, 0) \
    X(glDepthRange, compiled, 0) \
    X(glDisable, compiled, 0) \
    X(glDisableClientState, immediate, 0) \
    X(glDrawArrays, dereferenced, 0) \
    X(glDrawBuffer, compiled, 0) \
    X(glDrawElements, dereferenced, elementBytes) \
    X(glDrawPixels, dereferenced, drawPixelsBytes) \
    X(glEdgeFlag, compiled, 0) \
    X(glEdgeFlagPointer, immediate, 0) \
    X(glEdgeFlagv, compiled, 1) \
    X(glEnable, compiled, 0) \
    X(glEnableClientState, immediate, 0) \
    X(glEnd, compiled, 0) \
    X(glEndList, immediate, 0) \
    X(glEvalCoord1d, compiled, 0) \
    X(glEvalCoord1dv, compiled, 1) \
    X(glEvalCoord1f, compiled, 0) \
    X(glEvalCoord1fv, compiled, 1) \
    X(glEvalCoord2d, compiled, 0) \
    X(glEvalCoord2dv, compiled, 2) \
    X(glEvalCoord2f, compiled, 0) \
    X(glEvalCoord2fv, compiled, 2) \
    X(glEvalMesh1, compiled, 0) \
    X(glEvalMesh2, compiled, 0) \
    X(glEvalPoint1, compiled, 0) \
    X(glEvalPoint2, compiled, 0) \
    X(glFeedbackBuffer, immediate, 0) \
    X(glFinish, immediate, 0) \
    X(glFlush, immediate, 0) \
    X(glFogf, compiled, 0) \
    X(glFogfv, compiled, fogCount<GLfloat>) \
    X(glFogi, compiled, 0) \
    X(glFogiv, compiled, fogCount<GLint>) \
    X(glFrontFace, compiled, 0) \
    X(glFrustum, compiled, 0) \
    X(glGenLists, immediate, 0) \
    X(glGenTextures, immediate, generatedCount) \
    X(glGetBooleanv, query, 0) \
    X(glGetClipPlane, query, 0) \
    X(glGetDoublev, query, 0) \
    X(glGetError, query, 0) \
    X(glGetFloatv, query, 0) \
    X(glGetIntegerv, query, 0) \
    X(glGetLightfv, query, 0) \
    X(glGetLightiv, query, 0) \
    X(glGetMapdv, query, 0) \
    X(glGetMapfv, query, 0) \
    X(glGetMapiv, query, 0) \
    X(glGetMaterialfv, query, 0) \
    X(glGetMaterialiv, query, 0) \
    X(glGetPixelMapfv, query, 0) \
    X(glGetPixelMapuiv, query, 0) \
    X(glGetPixelMapusv, query, 0) \
    X(glGetPointerv, query, 0) \
    X(glGetPolygonStipple, query, 0) \
    X(glGetString, query, 0) \
    X(glGetTexEnvfv, query, 0) \
    X(glGetTexEnviv, query, 0) \
    X(glGetTexGendv, query, 0) \
    X(glGetTexGenfv, query, 0) \
    X(glGetTexGeniv, query, 0) \
    X(glGetTexImage, query, 0) \
    X(glGetTexLevelParameterfv, query, 0) \
    X(glGetTexLevelParameteriv, query, 0) \
    X(glGetTexParameterfv, query, 0) \
    X(glGetTexParameteriv, query, 0) \
    X(glHint, compiled, 0) \
    X(glIndexMask, compiled, 0) \
    X(glIndexPointer, immediate, 0) \
    X(glIndexd, compiled, 0) \
    X(glIndexdv, compiled, 1) \
    X(glIndexf, compiled, 0) \
    X(glIndexfv, compiled, 1) \
    X(glIndexi, compiled, 0) \
    X(glIndexiv, compiled, 1) \
    X(glIndexs, compiled, 0) \
    X(glIndexsv, compiled, 1) \
    X(glIndexub, compiled, 0) \
    X(glIndexubv, compiled, 1) \
    X(glInitNames, compiled, 0) \
    X(glInterleavedArrays, immediate, 0) \
    X(glIsEnabled, query, 0) \
    X(glIsList, query, 0) \
    X(glIsTexture, query, 0) \
    X(glLightModelf, compiled, 0) \
    X(glLightModelfv, compiled, lightModelCount<GLfloat>) \
    X(glLightModeli, compiled, 0) \
    X(glLightModeliv, compiled, lightModelCount<GLint>) \
    X(glLightf, compiled, 0) \
    X(glLightfv, compiled, lightCount<GLfloat>) \
    X(glLighti, compiled, 0) \
    X(glLightiv, compiled, lightCount<GLint>) \
    X(glLineStipple, compiled, 0) \
    X(glLineWidth, compiled, 0) \
    X(glListBase, compiled, 0) \
    X(glLoadIdentity, compiled, 0) \
    X(glLoadMatrixd, compiled, 16) \
    X(glLoadMatrixf, compiled, 16) \
    X(glLoadName, compiled, 0) \
    X(glLogicOp, compiled, 0) \
    X(glMap1d, compiled, map1Count<GLdouble>) \
    X(glMap1f, compiled, map1Count<GLfloat>) \
    X(glMap2d, compiled, map2Count<GLdouble>) \
    X(glMap2f, compiled, map2Count<GLfloat>) \
    X(glMapGrid1d, compiled, 0) \
    X(glMapGrid1f, compiled, 0) \
    X(glMapGrid2d, compiled, 0) \
    X(glMapGrid2f, compiled, 0) \
    X(glMaterialf, compiled, 0) \
    X(glMaterialfv, compiled, materialCount<GLfloat>) \
    X(glMateriali, compiled, 0) \
    X(glMaterialiv, compiled, materialCount<GLint>) \
    X(glMatrixMode, compiled, 0) \
    X(glMultMatrixd, compiled, 16) \
    X(glMultMatrixf, compiled, 16) \
    X(glNewList, immediate, 0) \
    X(glNormal3b, compiled, 0) \
    X(glNormal3bv, compiled, 3) \
    X(glNormal3d, compiled, 0) \
    X(glNormal3dv, compiled, 3) \
    X(glNormal3f, compiled, 0) \
    X(glNormal3fv, compiled, 3) \
    X(glNormal3i, compiled, 0) \
    X(glNormal3iv, compiled, 3) \
    X(glNormal3s, compiled, 0) \
    X(glNormal3sv, compiled, 3) \
    X(glNormalPointer, immediate, 0) \
    X(glOrtho, compiled, 0) \
    X(glPassThrough, compiled, 0) \
    X(glPixelMapfv, compiled, pixelMapCount<GLfloat>) \
    X(glPixelMapuiv, compiled, pixelMapCount<GLuint>) \
    X(glPixelMapusv, compiled, pixelMapCount<GLushort>) \
    X(glPixelStoref, immediate, 0) \
    X(glPixelStorei, immediate, 0) \
    X(glPixelTransferf, compiled, 0) \
    X(glPixelTransferi, compiled, 0) \
    X(glPixelZoom, compiled, 0) \
    X(glPointSize, compiled, 0) \
    X(glPolygonMode, compiled, 0) \
    X(glPolygonOffset, compiled, 0) \
    X(glPolygonStipple, dereferenced, polygonStippleBytes) \
    X(glPopAttrib, compiled, 0) \
    X(glPopClientAttrib, immediate, 0) \
    X(glPopMatrix, compiled, 0) \
    X(glPopName, compiled, 0) \
    X(glPrioritizeTextures, compiled, priorityCount) \
    X(glPushAttrib, compiled, 0) \
    X(glPushClientAttrib, immediate, 0) \
    X(glPushMatrix, compiled, 0) \
    X(glPushName, compiled, 0) \
    X(glRasterPos2d, compiled, 0) \
    X(glRasterPos2dv, compiled, 2) \
    X(glRasterPos2f, compiled, 0) \
    X(glRasterPos2fv, compiled, 2) \
    X(glRasterPos2i, compiled, 0) \
    X(glRasterPos2iv, compiled, 2) \
    X(glRasterPos2s, compiled, 0) \
    X(glRasterPos2sv, compiled, 2) \
    X(glRasterPos3d, compiled, 0) \
    X(glRasterPos3dv, compiled, 3) \
    X(glRasterPos3f, compiled, 0) \
    X(glRasterPos3fv, compiled, 3) \
    X(glRasterPos3i, compiled, 0) \
    X(glRasterPos3iv, compiled, 3) \
    X(glRasterPos3s, compiled, 0) \
    X(glRasterPos3sv, compiled, 3) \
    X(glRasterPos4d, compiled, 0) \
    X(glRasterPos4dv, compiled, 4) \
    X(glRasterPos4f, compiled, 0) \
    X(glRasterPos4fv, compiled, 4) \
    X(glRasterPos4i, compiled, 0) \
    X(glRasterPos4iv, compiled, 4) \
    X(glRasterPos4s, compiled, 0) \
    X(glRasterPos4sv, compiled, 4) \
    X(glReadBuffer, compiled, 0) \
    X(glReadPixels, query, 0) \
    X(glRectd, compiled, 0) \
    X(glRectdv, compiled, 2) \
    X(glRectf, compiled, 0) \
    X(glRectfv, compiled, 2) \
    X(glRecti, compiled, 0) \
    X(glRectiv, compiled, 2) \
    X(glRects, compiled, 0) \
    X(glRectsv, compiled, 2) \
    X(glRenderMode, immediate, 0) \
    X(glRotated, compiled, 0) \
    X(glRotatef, compiled, 0) \
    X(glScaled, compiled, 0) \
    X(glScalef, compiled, 0) \
    X(glScissor, compiled, 0) \
    X(glSelectBuffer, immediate, 0) \
    X(glShadeModel, compiled, 0) \
    X(glStencilFunc, compiled, 0) \
    X(glStencilMask, compiled, 0) \
    X(glStencilOp, compiled, 0) \
    X(glTexCoord1d, compiled, 0) \
    X(glTexCoord1dv, compiled, 1) \
    X(glTexCoord1f, compiled, 0) \
    X(glTexCoord1fv, compiled, 1) \
    X(glTexCoord1i, compiled, 0) \
    X(glTexCoord1iv, compiled, 1) \
    X(glTexCoord1s, compiled, 0) \
    X(glTexCoord1sv, compiled, 1) \
    X(glTexCoord2d, compiled, 0) \
    X(glTexCoord2dv, compiled, 2) \
    X(glTexCoord2f, compiled, 0) \
    X(glTexCoord2fv, compiled, 2) \
    X(glTexCoord2i, compiled, 0) \
    X(glTexCoord2iv, compiled, 2) \
    X(glTexCoord2s, compiled, 0) \
    X(glTexCoord2sv, compiled, 2) \
    X(glTexCoord3d, compiled, 0) \
    X(glTexCoord3dv, compiled, 3) \
    X(glTexCoord3f, compiled, 0) \
    X(glTexCoord3fv, compiled, 3) \
    X(glTexCoord3i, compiled, 0) \
    X(glTexCoord3iv, compiled, 3) \
    X(glTexCoord3s, compiled, 0) \
    X(glTexCoord3sv, compiled, 3) \
    X(glTexCoord4d, compiled, 0) \
    X(glTexCoord4dv, compiled, 4) \
    X(glTexCoord4f, compiled, 0) \
    X(glTexCoord4fv, compiled, 4) \
    X(glTexCoord4i, compiled, 0) \
    X(glTexCoord4iv, compiled, 4) \
    X(glTexCoord4s, compiled, 0) \
    X(glTexCoord4sv, compiled, 4) \
    X(glTexCoordPointer, immediate, 0) \
    X(glTexEnvf, compiled, 0) \
    X(glTexEnvfv, compiled, texEnvCount<GLfloat>) \
    X(glTexEnvi, compiled, 0) \
    X(glTexEnviv, compiled, texEnvCount<GLint>) \
    X(glTexGend, compiled, 0) \
    X(glTexGendv, compiled, texGenCount<GLdouble>) \
    X(glTexGenf, compiled, 0) \
    X(glTexGenfv, compiled, texGenCount<GLfloat>) \
    X(glTexGeni, compiled, 0) \
    X(glTexGeniv, compiled, texGenCount<GLint>) \
    X(glTexImage1D, dereferenced, texImage1DBytes) \
    X(glTexImage2D, dereferenced, texImage2DBytes) \
    X(glTexParameterf, compiled, 0) \
    X(glTexParameterfv, compiled, texParameterCount<GLfloat>) \
    X(glTexParameteri, compiled, 0) \
    X(glTexParameteriv, compiled, texParameterCount<GLint>) \
    X(glTexSubImage1D, dereferenced, texSubImage1DBytes) \
    X(glTexSubImage2D, dereferenced, texSubImage2DBytes) \
    X(glTranslated, compiled, 0) \
    X(glTranslatef, compiled, 0) \
    X(glVertex2d, compiled, 0) \
    X(glVertex2dv, compiled, 2) \
    X(glVertex2f, compiled, 0) \
    X(glVertex2fv, compiled, 2) \
    X(glVertex2i, compiled, 0) \
    X(glVertex2iv, compiled, 2) \
    X(glVertex2s, compiled, 0) \
    X(glVertex2sv, compiled, 2) \
    X(glVertex3d, compiled, 0) \
    X(glVertex3dv, compiled, 3) \
    X(glVertex3f, compiled, 0) \
    X(glVertex3fv, compiled, 3) \
    X(glVertex3i, compiled, 0) \
    X(glVertex3iv, compiled, 3) \
    X(glVertex3s, compiled, 0) \
    X(glVertex3sv, compiled, 3) \
    X(glVertex4d, compiled, 0) \
    X(glVertex4dv, compiled, 4) \
    X(glVertex4f, compiled, 0) \
    X(glVertex4fv, compiled, 4) \
    X(glVertex4i, compiled, 0) \
    X(glVertex4iv, compiled, 4) \
    X(glVertex4s, compiled, 0) \
    X(glVertex4sv, compiled, 4) \
    X(glVertexPointer, immediate, 0) \
    X(glViewport, compiled, 0)
// clang-format on

namespace glcalls {

enum class ListClass { compiled, dereferenced, immediate, query };

namespace call {
// One struct per function (named by glad's macro, i.e. glad_NAME): its name, class, count rule
// and glad's function pointer type.
#define MYGL_CALL_ENTRY(name, class_, count)                   \
    struct name {                                              \
        static constexpr const char* kName = #name;            \
        static constexpr ListClass kClass = ListClass::class_; \
        static constexpr auto kCount = count;                  \
        using Signature = decltype(::glad_##name);             \
    };
MYGL_GL11_CALLS(MYGL_CALL_ENTRY)
#undef MYGL_CALL_ENTRY
}  // namespace call

struct Function {
    const char* name;
    ListClass listClass;
};
// Every function of the list, in its order.
inline constexpr Function kFunctions[] = {
#define MYGL_FUNCTION(name, class_, count) {#name, ListClass::class_},
    MYGL_GL11_CALLS(MYGL_FUNCTION)
#undef MYGL_FUNCTION
};

}  // namespace glcalls
