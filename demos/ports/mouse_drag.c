/* Mouse drag rotation: the left button drags the model around, the middle button zooms, and a
 * passive-motion callback tracks the cursor; entering and leaving the window is reported.
 * Headless the mouse never moves, so the model keeps its starting pose. Ported by changing
 * only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static int dragging = 0, zooming = 0, lastX, lastY;
static float rotX = 25.0f, rotY = -30.0f, zoom = 6.0f;
static int cursorX, cursorY, inside = 1;

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -zoom);
    glRotatef(rotX, 1.0f, 0.0f, 0.0f);
    glRotatef(rotY, 0.0f, 1.0f, 0.0f);
    glColor3f(inside ? 1.0f : 0.5f, 0.9f, 0.6f);
    glutWireTeapot(1.2);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
}

static void mouse(int button, int state, int x, int y) {
    if (button == GLUT_LEFT_BUTTON) dragging = state == GLUT_DOWN;
    if (button == GLUT_MIDDLE_BUTTON) zooming = state == GLUT_DOWN;
    lastX = x;
    lastY = y;
}

static void motion(int x, int y) {
    if (dragging) {
        rotY += (float)(x - lastX);
        rotX += (float)(y - lastY);
    }
    if (zooming) zoom += 0.05f * (float)(y - lastY);
    lastX = x;
    lastY = y;
    glutPostRedisplay();
}

static void passive(int x, int y) {
    cursorX = x;
    cursorY = y;
}

static void entry(int state) {
    inside = state == GLUT_ENTERED;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(360, 270);
    glutCreateWindow("Drag to rotate");
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutPassiveMotionFunc(passive);
    glutEntryFunc(entry);
    glutMainLoop();
    return 0;
}
