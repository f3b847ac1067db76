/* A ball bouncing in a box, moved by a timer at a fixed step: the classic first animation.
 * The ball is a polygon of 24 sides, the box a line loop. Ported by changing only the
 * include (was <GL/glut.h>). */
#include <math.h>
#include <mygl/glut.h>

static GLfloat x = 60.0f, y = 150.0f, dx = 7.0f, dy = -5.0f;
static const GLfloat radius = 20.0f;
static int width = 320, height = 240;

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.6f, 0.6f, 0.6f);
    glBegin(GL_LINE_LOOP);
    glVertex2f(5.0f, 5.0f);
    glVertex2f((GLfloat)width - 5.0f, 5.0f);
    glVertex2f((GLfloat)width - 5.0f, (GLfloat)height - 5.0f);
    glVertex2f(5.0f, (GLfloat)height - 5.0f);
    glEnd();
    glColor3f(1.0f, 0.4f, 0.1f);
    glBegin(GL_POLYGON);
    for (i = 0; i < 24; i++) {
        float a = 2.0f * 3.14159265f * (float)i / 24.0f;
        glVertex2f(x + radius * cosf(a), y + radius * sinf(a));
    }
    glEnd();
    glutSwapBuffers();
}

static void timer(int value) {
    x += dx;
    y += dy;
    if (x - radius < 5.0f || x + radius > (GLfloat)width - 5.0f) dx = -dx;
    if (y - radius < 5.0f || y + radius > (GLfloat)height - 5.0f) dy = -dy;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value);
}

static void reshape(int w, int h) {
    width = w;
    height = h;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, w, 0.0, h);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(width, height);
    glutCreateWindow("Bouncing ball");
    glClearColor(0.0f, 0.0f, 0.2f, 1.0f);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(16, timer, 0);
    glutMainLoop();
    return 0;
}
