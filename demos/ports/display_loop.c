/* A program that never returns from its display function: it animates in its own loop and
 * calls glutSwapBuffers for every frame, as some tutorials do. Each swap is a frame, so the
 * capture still ends. Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static void display(void) {
    float t = 0.0f;
    for (;;) {
        glClear(GL_COLOR_BUFFER_BIT);
        glLoadIdentity();
        glRotatef(t, 0.0f, 0.0f, 1.0f);
        glBegin(GL_QUADS);
        glColor3f(1.0f, 0.0f, 0.0f);
        glVertex2f(-0.5f, -0.5f);
        glColor3f(0.0f, 1.0f, 0.0f);
        glVertex2f(0.5f, -0.5f);
        glColor3f(0.0f, 0.0f, 1.0f);
        glVertex2f(0.5f, 0.5f);
        glColor3f(1.0f, 1.0f, 0.0f);
        glVertex2f(-0.5f, 0.5f);
        glEnd();
        glutSwapBuffers();
        t += 10.0f;
    }
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(240, 240);
    glutCreateWindow("Loop in display");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
