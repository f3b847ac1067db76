/* Tessellation with edge flags: with a GLU_TESS_EDGE_FLAG callback GLU emits separate triangles
 * and marks which of their edges lie on the polygon's boundary. Passed on to glEdgeFlag, a
 * glPolygonMode(GL_LINE) drawing shows the outline only, without the inner diagonals (right);
 * left, the same polygon with every triangle edge. A letter-E shaped contour with a square hole. */
#include <stdlib.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

static GLUtesselator* tess;
static GLdouble letter[12][3] = {{-1, -1, 0},     {1, -1, 0},     {1, -0.6, 0},  {-0.5, -0.6, 0},
                                 {-0.5, -0.2, 0}, {0.6, -0.2, 0}, {0.6, 0.2, 0}, {-0.5, 0.2, 0},
                                 {-0.5, 0.6, 0},  {1, 0.6, 0},    {1, 1, 0},     {-1, 1, 0}};
static GLdouble hole[4][3] = {{-0.85, -0.15, 0}, {-0.85, 0.15, 0}, {-0.65, 0.15, 0}, {-0.65, -0.15, 0}};
static int useFlags;

static void beginCallback(GLenum mode) { glBegin(mode); }
static void endCallback(void) { glEnd(); }
static void vertexCallback(GLvoid* vertex) { glVertex3dv((const GLdouble*)vertex); }
static void edgeFlagCallback(GLboolean flag) { glEdgeFlag(flag); }
static void ignoreEdgeFlag(GLboolean flag) { (void)flag; }

static void drawLetter(void) {
    int i;
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (i = 0; i < 12; ++i) gluTessVertex(tess, letter[i], letter[i]);
    gluTessEndContour(tess);
    gluTessBeginContour(tess);
    for (i = 0; i < 4; ++i) gluTessVertex(tess, hole[i], hole[i]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

static void display(void) {
    int side;
    glClear(GL_COLOR_BUFFER_BIT);
    for (side = 0; side < 2; ++side) {
        useFlags = side;
        gluTessCallback(tess, GLU_TESS_EDGE_FLAG,
                        useFlags ? (_GLUfuncptr)edgeFlagCallback : (_GLUfuncptr)ignoreEdgeFlag);
        glLoadIdentity();
        glTranslatef(side ? 1.2f : -1.2f, 0.0f, 0.0f);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glColor3f(0.2f, 0.3f, 0.5f);
        drawLetter();
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glColor3f(1.0f, 0.85f, 0.3f);
        drawLetter();
        glEdgeFlag(GL_TRUE);
    }
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-2.5, 2.5, -1.3, 1.3);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 210);
    glutCreateWindow("edge flags from the tessellator");
    glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)endCallback);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
