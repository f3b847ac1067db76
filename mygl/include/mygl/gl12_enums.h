/* The GL 1.2 enums MyGL implements, for programs whose <GL/gl.h> gave them: the loader
 * (<glad/gl.h>) is generated for GL 1.1 only. Included by <mygl/glu.h> and <mygl/glut.h>. */
#ifndef MYGL_GL12_ENUMS_H
#define MYGL_GL12_ENUMS_H

#include <glad/gl.h>

/* Lighting */
#ifndef GL_RESCALE_NORMAL
#define GL_RESCALE_NORMAL 0x803A
#endif
#ifndef GL_LIGHT_MODEL_COLOR_CONTROL
#define GL_LIGHT_MODEL_COLOR_CONTROL 0x81F8
#define GL_SINGLE_COLOR 0x81F9
#define GL_SEPARATE_SPECULAR_COLOR 0x81FA
#endif

/* Textures and pixels */
#ifndef GL_CLAMP_TO_EDGE
#define GL_CLAMP_TO_EDGE 0x812F
#endif
#ifndef GL_BGR
#define GL_BGR 0x80E0
#define GL_BGRA 0x80E1
#endif

#endif
