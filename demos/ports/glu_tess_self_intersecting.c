/* Tessellation: self-intersecting contours (a pentagram and a figure eight). Where edges cross
 * GLU asks the COMBINE callback for a new vertex; this one mixes the colours of the four
 * vertices with GLU's weights, so every vertex carries x, y, z, r, g, b. 'r' steps through the
 * winding rules (the pentagram's centre winds twice: ODD leaves it empty). */
#include <math.h>
#include <stdlib.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

#define PI 3.14159265358979323846
#define MAX_COMBINED 256

static GLUtesselator* tess;
static GLdouble pentagram[5][6], eight[8][6];
static GLdouble combined[MAX_COMBINED][6];
static int combinedCount = 0;
static const GLenum rules[3] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_ABS_GEQ_TWO};
static int rule = 0;

static void beginCallback(GLenum mode) { glBegin(mode); }
static void endCallback(void) { glEnd(); }
static void vertexCallback(GLvoid* data) {
    const GLdouble* v = (const GLdouble*)data;
    glColor3dv(v + 3);
    glVertex3dv(v);
}

static void combineCallback(GLdouble coords[3], GLdouble* neighbours[4], GLfloat weights[4], GLdouble** out) {
    GLdouble* v;
    int i, k;
    if (combinedCount == MAX_COMBINED) combinedCount = 0; /* reused: each polygon needs few */
    v = combined[combinedCount++];
    for (k = 0; k < 3; ++k) v[k] = coords[k];
    for (k = 3; k < 6; ++k) {
        v[k] = 0.0;
        for (i = 0; i < 4; ++i) {
            if (neighbours[i]) v[k] += weights[i] * neighbours[i][k];
        }
    }
    *out = v;
}

static void contour(GLdouble (*points)[6], int count) {
    int i;
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (i = 0; i < count; ++i) gluTessVertex(tess, points[i], points[i]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[rule]);
    combinedCount = 0;
    glLoadIdentity();
    glTranslatef(-1.1f, 0.0f, 0.0f);
    contour(pentagram, 5);
    glLoadIdentity();
    glTranslatef(1.1f, 0.0f, 0.0f);
    contour(eight, 8);
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-2.2, 2.2, -1.2, 1.2);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'r') rule = (rule + 1) % 3;
    if (key == 27) exit(0);
    glutPostRedisplay();
}

static void timer(int value) {
    rule = (rule + 1) % 3;
    glutPostRedisplay();
    glutTimerFunc(1000, timer, value);
}

static void setVertex(GLdouble* v, double x, double y, double r, double g, double b) {
    v[0] = x;
    v[1] = y;
    v[2] = 0.0;
    v[3] = r;
    v[4] = g;
    v[5] = b;
}

int main(int argc, char** argv) {
    int i;
    for (i = 0; i < 5; ++i) { /* every second point of a pentagon */
        const double a = PI / 2 + i * 4 * PI / 5;
        setVertex(pentagram[i], cos(a), sin(a), i % 2, 0.4 + 0.1 * i, 1.0 - 0.2 * i);
    }
    for (i = 0; i < 8; ++i) { /* a figure eight: two of its edges cross in the middle */
        const double a = 2 * PI * (i + 0.5) / 8;
        setVertex(eight[i], 0.8 * sin(a), 0.9 * sin(a) * cos(a) * 2.0, 1.0, 0.3 + 0.08 * i, 0.2);
    }
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(440, 240);
    glutCreateWindow("self-intersecting contours");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glShadeModel(GL_SMOOTH);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)endCallback);
    gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combineCallback);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(1000, timer, 0);
    glutMainLoop();
    return 0;
}
