/* Quadrics: a pie chart from gluPartialDisk slices (start angle and sweep in degrees, measured
 * clockwise from +y), with a doughnut of gluDisk rings below. Keys 1-5 pull a slice out. */
#include <math.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

#define PI 3.14159265358979323846

static GLUquadricObj* quadric;
static const double shares[5] = {35.0, 25.0, 20.0, 12.0, 8.0};
static const float colors[5][3] = {
    {0.90f, 0.30f, 0.25f}, {0.95f, 0.75f, 0.20f}, {0.30f, 0.75f, 0.40f}, {0.25f, 0.55f, 0.95f}, {0.65f, 0.40f, 0.85f}};
static int pulled = 0;

static void display(void) {
    double start = 0.0;
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
    for (i = 0; i < 5; ++i) {
        const double sweep = shares[i] * 3.6;
        const double middle = (start + sweep / 2.0) * PI / 180.0;
        glPushMatrix();
        glTranslated(-1.4, 0.3, 0.0);
        if (i == pulled) glTranslated(0.2 * sin(middle), 0.2 * cos(middle), 0.0);
        glColor3fv(colors[i]);
        gluPartialDisk(quadric, 0.0, 1.0, 24, 3, start, sweep);
        glColor3f(0.05f, 0.05f, 0.05f);
        gluQuadricDrawStyle(quadric, GLU_SILHOUETTE);
        gluPartialDisk(quadric, 0.0, 1.0, 24, 3, start, sweep);
        gluQuadricDrawStyle(quadric, GLU_FILL);
        glPopMatrix();
        start += sweep;
    }
    /* a doughnut chart: the same shares as rings of one disk */
    start = 0.0;
    for (i = 0; i < 5; ++i) {
        glPushMatrix();
        glTranslated(1.4, 0.3, 0.0);
        glColor3fv(colors[i]);
        gluPartialDisk(quadric, 0.5, 1.0, 32, 1, start, shares[i] * 3.6);
        glPopMatrix();
        start += shares[i] * 3.6;
    }
    glColor3f(0.9f, 0.9f, 0.9f);
    glTranslated(1.4, 0.3, 0.0);
    gluQuadricDrawStyle(quadric, GLU_LINE);
    gluDisk(quadric, 0.3, 0.45, 16, 2);
    gluQuadricDrawStyle(quadric, GLU_FILL);
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    const double aspect = (double)width / (double)height;
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-2.8 * aspect / 1.6, 2.8 * aspect / 1.6, -1.5, 1.8);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key >= '1' && key <= '5') pulled = key - '1';
    glutPostRedisplay();
}

static void timer(int value) {
    pulled = (value + 1) % 5;
    glutPostRedisplay();
    glutTimerFunc(700, timer, value + 1);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(512, 320);
    glutCreateWindow("GLU pie chart");
    glClearColor(0.95f, 0.95f, 0.92f, 1.0f);
    quadric = gluNewQuadric();
    gluQuadricNormals(quadric, GLU_NONE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(700, timer, 0);
    glutMainLoop();
    return 0;
}
