/* Built as C99 against the installed package: tessellates a square with a square hole through
 * GLU's callbacks and projects a point, none of which needs a GL context. Exits 0 if the
 * triangles cover the ring's area (16 - 4) and the point lands in the viewport's centre. */
#include <mygl/glu.h>

#include <math.h>
#include <stdio.h>

static double corners[3][3];
static int corner;
static double area;

static void vertex(void* data) {
    const double* p = (const double*)data;
    int k;
    for (k = 0; k < 3; ++k) corners[corner][k] = p[k];
    if (++corner == 3) {
        area += ((corners[1][0] - corners[0][0]) * (corners[2][1] - corners[0][1]) -
                 (corners[1][1] - corners[0][1]) * (corners[2][0] - corners[0][0])) /
                2.0;
        corner = 0;
    }
}

int main(void) {
    static GLdouble outer[4][3] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
    static GLdouble inner[4][3] = {{1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}};
    const GLdouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const GLint viewport[4] = {0, 0, 640, 480};
    GLdouble x, y, z;
    GLUtesselator* tess = gluNewTess();
    int k;
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertex);
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (k = 0; k < 4; ++k) gluTessVertex(tess, outer[k], outer[k]);
    gluTessEndContour(tess);
    gluTessBeginContour(tess);
    for (k = 0; k < 4; ++k) gluTessVertex(tess, inner[k], inner[k]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
    gluDeleteTess(tess);
    if (!gluProject(0, 0, 0, identity, identity, viewport, &x, &y, &z)) return 1;
    printf("GLU %s: ring area %g, origin at (%g, %g), %s\n", (const char*)gluGetString(GLU_VERSION), area, x, y,
           (const char*)gluErrorString(GLU_INVALID_ENUM));
    return fabs(area - 12.0) < 1e-12 && x == 320.0 && y == 240.0 ? 0 : 1;
}
