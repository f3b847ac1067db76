/* Reshape handling: the projection keeps the aspect ratio whatever the window's shape, and the
 * program asks for a new window size itself after a few frames (glutReshapeWindow), so the
 * reshape callback runs again. Ported by changing only the include. */
#include <mygl/glut.h>

static int frames = 0;

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.2f, 0.6f, 1.0f);
    glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
    glColor3f(1.0f, 0.9f, 0.2f);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.9f, -0.8f);
    glVertex2f(0.9f, -0.8f);
    glVertex2f(0.0f, 0.9f);
    glEnd();
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINE_LOOP);
    glVertex2f(-1.2f, -1.2f);
    glVertex2f(1.2f, -1.2f);
    glVertex2f(1.2f, 1.2f);
    glVertex2f(-1.2f, 1.2f);
    glEnd();
    glutSwapBuffers();
    if (++frames == 1) glutReshapeWindow(200, 300);
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (w <= h)
        glOrtho(-1.5, 1.5, -1.5 * (GLfloat)h / (GLfloat)w, 1.5 * (GLfloat)h / (GLfloat)w, -10.0, 10.0);
    else
        glOrtho(-1.5 * (GLfloat)w / (GLfloat)h, 1.5 * (GLfloat)w / (GLfloat)h, -1.5, 1.5, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 240);
    glutCreateWindow("Reshape");
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
