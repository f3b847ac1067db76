/* The Red Book's double-buffered spinning square: the idle callback turns it, the left button
 * starts and the right button stops the spin. Ported by changing only the include. */
#include <mygl/glut.h>

static GLfloat spin = 0.0f;

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    glPushMatrix();
    glRotatef(spin, 0.0f, 0.0f, 1.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRectf(-25.0f, -25.0f, 25.0f, 25.0f);
    glPopMatrix();
    glutSwapBuffers();
}

static void spinDisplay(void) {
    spin = spin + 2.0f;
    if (spin > 360.0f) spin = spin - 360.0f;
    glutPostRedisplay();
}

static void init(void) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glShadeModel(GL_FLAT);
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-50.0, 50.0, -50.0, 50.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void mouse(int button, int state, int x, int y) {
    (void)x, (void)y;
    if (button == GLUT_LEFT_BUTTON && state == GLUT_DOWN) glutIdleFunc(spinDisplay);
    if (button == GLUT_RIGHT_BUTTON && state == GLUT_DOWN) glutIdleFunc(NULL);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(250, 250);
    glutInitWindowPosition(100, 100);
    glutCreateWindow(argv[0]);
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutIdleFunc(spinDisplay);
    glutMainLoop();
    return 0;
}
