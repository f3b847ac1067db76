/* MyGL's GLU: the OpenGL Utility Library for C and C++ programs. Replace `#include <GL/glu.h>`
 * with `#include <mygl/glu.h>` and link mygl::glu. Every GL call GLU makes goes through the
 * loaded GL table (<glad/gl.h>), so the same calls reach whichever backend is current.
 * The names and values are GLU 1.3's; NURBS are not provided. */
#ifndef MYGL_GLU_H
#define MYGL_GLU_H

#include <glad/gl.h>
#include <mygl/gl12_enums.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLU_FALSE 0
#define GLU_TRUE 1

#define GLU_VERSION_1_1 1
#define GLU_VERSION_1_2 1
#define GLU_VERSION_1_3 1

/* gluGetString */
#define GLU_VERSION 100800
#define GLU_EXTENSIONS 100801

/* Errors */
#define GLU_INVALID_ENUM 100900
#define GLU_INVALID_VALUE 100901
#define GLU_OUT_OF_MEMORY 100902
#define GLU_INCOMPATIBLE_GL_VERSION 100903
#define GLU_INVALID_OPERATION 100904

/* Quadric callback */
#define GLU_ERROR 100103

/* Quadric draw style, normals, orientation */
#define GLU_POINT 100010
#define GLU_LINE 100011
#define GLU_FILL 100012
#define GLU_SILHOUETTE 100013
#define GLU_SMOOTH 100000
#define GLU_FLAT 100001
#define GLU_NONE 100002
#define GLU_OUTSIDE 100020
#define GLU_INSIDE 100021

/* Tessellator callbacks */
#define GLU_TESS_BEGIN 100100
#define GLU_BEGIN 100100
#define GLU_TESS_VERTEX 100101
#define GLU_VERTEX 100101
#define GLU_TESS_END 100102
#define GLU_END 100102
#define GLU_TESS_ERROR 100103
#define GLU_TESS_EDGE_FLAG 100104
#define GLU_EDGE_FLAG 100104
#define GLU_TESS_COMBINE 100105
#define GLU_TESS_BEGIN_DATA 100106
#define GLU_TESS_VERTEX_DATA 100107
#define GLU_TESS_END_DATA 100108
#define GLU_TESS_ERROR_DATA 100109
#define GLU_TESS_EDGE_FLAG_DATA 100110
#define GLU_TESS_COMBINE_DATA 100111

/* Contour types of gluNextContour */
#define GLU_CW 100120
#define GLU_CCW 100121
#define GLU_INTERIOR 100122
#define GLU_EXTERIOR 100123
#define GLU_UNKNOWN 100124

/* Tessellator properties */
#define GLU_TESS_WINDING_RULE 100140
#define GLU_TESS_BOUNDARY_ONLY 100141
#define GLU_TESS_TOLERANCE 100142

/* Tessellator errors */
#define GLU_TESS_ERROR1 100151
#define GLU_TESS_ERROR2 100152
#define GLU_TESS_ERROR3 100153
#define GLU_TESS_ERROR4 100154
#define GLU_TESS_ERROR5 100155
#define GLU_TESS_ERROR6 100156
#define GLU_TESS_ERROR7 100157
#define GLU_TESS_ERROR8 100158
#define GLU_TESS_MISSING_BEGIN_POLYGON 100151
#define GLU_TESS_MISSING_BEGIN_CONTOUR 100152
#define GLU_TESS_MISSING_END_POLYGON 100153
#define GLU_TESS_MISSING_END_CONTOUR 100154
#define GLU_TESS_COORD_TOO_LARGE 100155
#define GLU_TESS_NEED_COMBINE_CALLBACK 100156

/* Winding rules */
#define GLU_TESS_WINDING_ODD 100130
#define GLU_TESS_WINDING_NONZERO 100131
#define GLU_TESS_WINDING_POSITIVE 100132
#define GLU_TESS_WINDING_NEGATIVE 100133
#define GLU_TESS_WINDING_ABS_GEQ_TWO 100134

#define GLU_TESS_MAX_COORD 1.0e150

typedef struct GLUquadric GLUquadric;
typedef struct GLUtesselator GLUtesselator;
typedef GLUquadric GLUquadricObj;
typedef GLUtesselator GLUtesselatorObj;
typedef GLUtesselator GLUtriangulatorObj;

/* Callbacks are passed as this type and cast back to their own signature by GLU. */
typedef void (*_GLUfuncptr)(void);

/* Matrices and projection */
void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar);
void gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY, GLdouble centerZ,
               GLdouble upX, GLdouble upY, GLdouble upZ);
void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);
void gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint* viewport);
GLint gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble* model, const GLdouble* proj,
                 const GLint* view, GLdouble* winX, GLdouble* winY, GLdouble* winZ);
GLint gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble* model, const GLdouble* proj,
                   const GLint* view, GLdouble* objX, GLdouble* objY, GLdouble* objZ);
GLint gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW, const GLdouble* model,
                    const GLdouble* proj, const GLint* view, GLdouble nearVal, GLdouble farVal, GLdouble* objX,
                    GLdouble* objY, GLdouble* objZ, GLdouble* objW);

/* Strings */
const GLubyte* gluErrorString(GLenum error);
const GLubyte* gluGetString(GLenum name);
GLboolean gluCheckExtension(const GLubyte* extName, const GLubyte* extString);

/* Quadrics */
GLUquadric* gluNewQuadric(void);
void gluDeleteQuadric(GLUquadric* quad);
void gluQuadricDrawStyle(GLUquadric* quad, GLenum draw);
void gluQuadricOrientation(GLUquadric* quad, GLenum orientation);
void gluQuadricNormals(GLUquadric* quad, GLenum normal);
void gluQuadricTexture(GLUquadric* quad, GLboolean texture);
void gluQuadricCallback(GLUquadric* quad, GLenum which, _GLUfuncptr callback);
void gluSphere(GLUquadric* quad, GLdouble radius, GLint slices, GLint stacks);
void gluCylinder(GLUquadric* quad, GLdouble base, GLdouble top, GLdouble height, GLint slices, GLint stacks);
void gluDisk(GLUquadric* quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops);
void gluPartialDisk(GLUquadric* quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops, GLdouble start,
                    GLdouble sweep);

/* Images and mipmaps */
GLint gluScaleImage(GLenum format, GLsizei wIn, GLsizei hIn, GLenum typeIn, const void* dataIn, GLsizei wOut,
                    GLsizei hOut, GLenum typeOut, GLvoid* dataOut);
GLint gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLenum format, GLenum type,
                        const void* data);
GLint gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLenum format, GLenum type,
                        const void* data);

/* Tessellator */
GLUtesselator* gluNewTess(void);
void gluDeleteTess(GLUtesselator* tess);
void gluTessBeginPolygon(GLUtesselator* tess, GLvoid* data);
void gluTessBeginContour(GLUtesselator* tess);
void gluTessVertex(GLUtesselator* tess, GLdouble* location, GLvoid* data);
void gluTessEndContour(GLUtesselator* tess);
void gluTessEndPolygon(GLUtesselator* tess);
void gluTessCallback(GLUtesselator* tess, GLenum which, _GLUfuncptr callback);
void gluTessProperty(GLUtesselator* tess, GLenum which, GLdouble data);
void gluGetTessProperty(GLUtesselator* tess, GLenum which, GLdouble* data);
void gluTessNormal(GLUtesselator* tess, GLdouble valueX, GLdouble valueY, GLdouble valueZ);
/* GLU 1.0's polygon calls, kept for old programs. */
void gluBeginPolygon(GLUtesselator* tess);
void gluNextContour(GLUtesselator* tess, GLenum type);
void gluEndPolygon(GLUtesselator* tess);

#ifdef __cplusplus
}
#endif

#endif /* MYGL_GLU_H */
