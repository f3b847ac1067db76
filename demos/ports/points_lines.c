/* Points and lines: point sizes 1 to 6, line widths 1 to 5, strips, loops and a fan of lines
 * with a colour per vertex. Ported by changing only the include (was <GL/glut.h>). */
#include <math.h>
#include <mygl/glut.h>

static int frame = 0;

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 1; i <= 6; i++) {
        glPointSize((GLfloat)i);
        glBegin(GL_POINTS);
        glColor3f(1.0f, 1.0f - 0.15f * (float)i, 0.2f);
        glVertex2f(20.0f + 25.0f * (float)i, 280.0f);
        glEnd();
    }
    glPointSize(1.0f);
    for (i = 1; i <= 5; i++) {
        glLineWidth((GLfloat)i);
        glBegin(GL_LINES);
        glColor3f(0.3f, 0.6f + 0.08f * (float)i, 1.0f);
        glVertex2f(20.0f, 250.0f - 15.0f * (float)i);
        glColor3f(1.0f, 0.3f, 0.3f);
        glVertex2f(180.0f, 230.0f - 15.0f * (float)i + (float)frame);
        glEnd();
    }
    glLineWidth(1.0f);
    glColor3f(0.2f, 1.0f, 0.4f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i <= 40; i++) glVertex2f(200.0f + 4.0f * (float)i, 250.0f + 30.0f * sinf(0.3f * (float)(i + frame)));
    glEnd();
    glColor3f(1.0f, 0.8f, 0.2f);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 7; i++) {
        float a = 2.0f * 3.14159265f * (float)i / 7.0f;
        glVertex2f(290.0f + 60.0f * cosf(a), 110.0f + 60.0f * sinf(a));
    }
    glEnd();
    glBegin(GL_LINES);
    for (i = 0; i < 16; i++) {
        float a = 2.0f * 3.14159265f * (float)i / 16.0f + 0.05f * (float)frame;
        glColor3f(1.0f, 1.0f, 1.0f);
        glVertex2f(100.0f, 100.0f);
        glColor3f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.5f);
        glVertex2f(100.0f + 70.0f * cosf(a), 100.0f + 70.0f * sinf(a));
    }
    glEnd();
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (GLdouble)w, 0.0, (GLdouble)h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void timer(int value) {
    frame = value;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value + 1);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Points and lines");
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(16, timer, 1);
    glutMainLoop();
    return 0;
}
