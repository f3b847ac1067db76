// A course-style 2D GLUT program animated with glutTimerFunc: a fan and a polygon in window
// coordinates. Ported to MyGL by changing only the include below (was <GL/glut.h>).
#include <mygl/glut.h>

#include <math.h>

static int tick = 0;

static void display(void) {
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, glutGet(GLUT_WINDOW_WIDTH), 0, glutGet(GLUT_WINDOW_HEIGHT));
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    int i;
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(100, 120);
    for (i = 0; i <= 16; ++i) {
        float a = 6.2831853f * i / 16 + 0.1f * tick;
        glColor3f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.5f);
        glVertex2f(100 + 80 * cosf(a), 120 + 80 * sinf(a));
    }
    glEnd();
    glColor3f(0.2f, 0.3f, 0.9f);
    glRectf(200.5f + tick, 40.25f, 290.0f, 200.0f);
    glutSwapBuffers();
}

static void timer(int value) {
    tick = value;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value + 1);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("2D with a timer");
    glutDisplayFunc(display);
    glutTimerFunc(16, timer, 1);
    glutMainLoop();
    return 0;
}
