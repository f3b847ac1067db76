/* The first program of every course: one smooth-shaded triangle, single-buffered, glFlush.
 * Ported to MyGL by changing only the include below (was <GL/glut.h>). */
#include <mygl/glut.h>

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2f(-0.8f, -0.7f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(0.8f, -0.6f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2f(0.1f, 0.8f);
    glEnd();
    glFlush();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("Hello triangle");
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
