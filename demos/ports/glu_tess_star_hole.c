/* Tessellation: a five-pointed star with a pentagonal hole (two contours, the hole wound the
 * other way), filled, with its boundary traced by GLU_TESS_BOUNDARY_ONLY on top. The star
 * turns; 'b' hides the outline. */
#include <math.h>
#include <stdlib.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

#define PI 3.14159265358979323846

static GLUtesselator* tess;
static GLdouble star[10][3], hole[5][3];
static float angle = 0.0f;
static int outline = 1;

static void beginCallback(GLenum mode) { glBegin(mode); }
static void endCallback(void) { glEnd(); }
static void vertexCallback(GLvoid* vertex) { glVertex3dv((const GLdouble*)vertex); }

static void polygon(void) {
    int i;
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (i = 0; i < 10; ++i) gluTessVertex(tess, star[i], star[i]);
    gluTessEndContour(tess);
    gluTessBeginContour(tess);
    for (i = 0; i < 5; ++i) gluTessVertex(tess, hole[i], hole[i]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);
    glColor3f(0.95f, 0.75f, 0.15f);
    polygon();
    if (outline) {
        gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
        glColor3f(0.8f, 0.1f, 0.1f);
        polygon();
    }
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-1.2, 1.2, -1.2, 1.2);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'b') outline = !outline;
    glutPostRedisplay();
}

static void idle(void) {
    angle += 5.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    int i;
    for (i = 0; i < 10; ++i) {
        const double a = PI / 2 + i * PI / 5, r = i % 2 ? 0.42 : 1.0;
        star[i][0] = r * cos(a);
        star[i][1] = r * sin(a);
        star[i][2] = 0.0;
    }
    for (i = 0; i < 5; ++i) { /* clockwise: a hole under the default odd winding rule */
        const double a = PI / 2 - i * 2 * PI / 5;
        hole[i][0] = 0.25 * cos(a);
        hole[i][1] = 0.25 * sin(a);
        hole[i][2] = 0.0;
    }
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 320);
    glutCreateWindow("star with a hole");
    glClearColor(0.12f, 0.15f, 0.3f, 1.0f);
    glLineWidth(2.0f);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)endCallback);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
