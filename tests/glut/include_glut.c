/* A C program's view of <mygl/glut.h>: the header alone, and the names a course program uses. */
#include <mygl/glut.h>

int uses_glut_names(void);
int uses_glut_names(void) {
    void* fonts[] = {GLUT_BITMAP_8_BY_13,        GLUT_BITMAP_9_BY_15,      GLUT_BITMAP_TIMES_ROMAN_10,
                     GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12,
                     GLUT_BITMAP_HELVETICA_18,   GLUT_STROKE_ROMAN,        GLUT_STROKE_MONO_ROMAN};
    (void)fonts;
    if (0) exit(0); /* <stdlib.h> comes with GLUT's header */
    return GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_ALPHA | GLUT_STENCIL | GLUT_ACCUM | GLUT_MULTISAMPLE;
}
