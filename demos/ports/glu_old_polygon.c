/* GLU 1.0's polygon calls, as older course notes use them: gluBeginPolygon, gluNextContour and
 * gluEndPolygon draw a frame (a square with a square hole) and a ring of eight notches; the
 * contours' types are only hints, the odd winding rule makes the inner ones holes. */
#include <math.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

#define PI 3.14159265358979323846

static GLUtriangulatorObj* tess;
static GLdouble frame[2][4][3] = {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
                                  {{-0.6, -0.6, 0}, {0.6, -0.6, 0}, {0.6, 0.6, 0}, {-0.6, 0.6, 0}}};
static GLdouble gear[32][3], hub[12][3];
static float angle = 0.0f;

static void beginCallback(GLenum mode) { glBegin(mode); }
static void endCallback(void) { glEnd(); }
static void vertexCallback(GLvoid* vertex) { glVertex3dv((const GLdouble*)vertex); }

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(-1.2f, 0.0f, 0.0f);
    glColor3f(0.7f, 0.5f, 0.3f);
    gluBeginPolygon(tess);
    for (i = 0; i < 4; ++i) gluTessVertex(tess, frame[0][i], frame[0][i]);
    gluNextContour(tess, GLU_INTERIOR);
    for (i = 0; i < 4; ++i) gluTessVertex(tess, frame[1][i], frame[1][i]);
    gluEndPolygon(tess);

    glLoadIdentity();
    glTranslatef(1.2f, 0.0f, 0.0f);
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    glColor3f(0.6f, 0.7f, 0.8f);
    gluBeginPolygon(tess);
    for (i = 0; i < 32; ++i) gluTessVertex(tess, gear[i], gear[i]);
    gluNextContour(tess, GLU_INTERIOR);
    for (i = 0; i < 12; ++i) gluTessVertex(tess, hub[i], hub[i]);
    gluEndPolygon(tess);
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-2.4, 2.4, -1.2, 1.2);
    glMatrixMode(GL_MODELVIEW);
}

static void idle(void) {
    angle += 4.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    int i;
    for (i = 0; i < 32; ++i) { /* eight teeth, four corners each */
        const double a = 2 * PI * (i / 4 + (i % 4 < 2 ? 0.1 * (i % 4) : 0.1 * (i % 4) + 0.2)) / 8;
        const double r = (i % 4 == 1 || i % 4 == 2) ? 1.0 : 0.8;
        gear[i][0] = r * cos(a);
        gear[i][1] = r * sin(a);
        gear[i][2] = 0.0;
    }
    for (i = 0; i < 12; ++i) {
        const double a = 2 * PI * i / 12;
        hub[i][0] = 0.3 * cos(a);
        hub[i][1] = 0.3 * sin(a);
        hub[i][2] = 0.0;
    }
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(480, 240);
    glutCreateWindow("gluBeginPolygon, gluNextContour, gluEndPolygon");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tess, GLU_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tess, GLU_END, (_GLUfuncptr)endCallback);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
