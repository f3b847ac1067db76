/* Picking a point with gluUnProject: a click reads the depth under the mouse (glReadPixels of
 * GL_DEPTH_COMPONENT) and turns window coordinates back into object coordinates, where a marker
 * is drawn; clicking the background drops the marker on the floor by unprojecting the near and
 * far points of the ray. Headless, a click at the window's centre is simulated. */
#include <mygl/glut.h>
#include <mygl/glu.h>

static GLUquadricObj* quadric;
static int pickX, pickY, pickPending = 1;
static GLdouble marker[3] = {0.0, 0.0, 0.0};
static int windowHeight = 320;

static void scene(void) {
    int i;
    glColor3f(0.3f, 0.35f, 0.3f);
    glBegin(GL_QUADS); /* the floor, y = 0 */
    glVertex3f(-4.0f, 0.0f, 4.0f);
    glVertex3f(4.0f, 0.0f, 4.0f);
    glVertex3f(4.0f, 0.0f, -4.0f);
    glVertex3f(-4.0f, 0.0f, -4.0f);
    glEnd();
    for (i = 0; i < 3; ++i) {
        glPushMatrix();
        glTranslatef(-2.0f + 2.0f * (float)i, 0.7f, -0.5f * (float)i);
        glColor3f(0.9f - 0.3f * (float)i, 0.4f, 0.3f + 0.3f * (float)i);
        gluSphere(quadric, 0.7, 20, 14);
        glPopMatrix();
    }
}

/* Where the ray under (x, y) meets the scene, from the depth buffer; on the background, where
 * it meets the floor plane. */
static void pick(int x, int y) {
    GLdouble model[16], proj[16], nearPoint[3], farPoint[3], t;
    GLint viewport[4];
    GLfloat depth = 1.0f;
    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    glGetIntegerv(GL_VIEWPORT, viewport);
    y = viewport[3] - 1 - y; /* GLUT's y runs down */
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    if (depth < 1.0f) {
        gluUnProject(x + 0.5, y + 0.5, depth, model, proj, viewport, &marker[0], &marker[1], &marker[2]);
        return;
    }
    gluUnProject(x + 0.5, y + 0.5, 0.0, model, proj, viewport, &nearPoint[0], &nearPoint[1], &nearPoint[2]);
    gluUnProject(x + 0.5, y + 0.5, 1.0, model, proj, viewport, &farPoint[0], &farPoint[1], &farPoint[2]);
    if (farPoint[1] == nearPoint[1]) return;
    t = nearPoint[1] / (nearPoint[1] - farPoint[1]);
    marker[0] = nearPoint[0] + t * (farPoint[0] - nearPoint[0]);
    marker[1] = 0.0;
    marker[2] = nearPoint[2] + t * (farPoint[2] - nearPoint[2]);
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 3.0, 6.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
    scene();
    if (pickPending) {
        pick(pickX, pickY);
        pickPending = 0;
    }
    glPushMatrix(); /* the marker: a small yellow ball with a cross */
    glTranslated(marker[0], marker[1], marker[2]);
    glColor3f(1.0f, 0.9f, 0.1f);
    glDisable(GL_DEPTH_TEST);
    glBegin(GL_LINES);
    glVertex3f(-0.3f, 0.0f, 0.0f);
    glVertex3f(0.3f, 0.0f, 0.0f);
    glVertex3f(0.0f, -0.3f, 0.0f);
    glVertex3f(0.0f, 0.3f, 0.0f);
    glEnd();
    gluSphere(quadric, 0.08, 8, 6);
    glEnable(GL_DEPTH_TEST);
    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    windowHeight = height;
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)width / (double)height, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void mouse(int button, int state, int x, int y) {
    if (button != GLUT_LEFT_BUTTON || state != GLUT_DOWN) return;
    pickX = x;
    pickY = y;
    pickPending = 1;
    glutPostRedisplay();
}

static void timer(int step) {
    /* walk the simulated click across the window: over the spheres, then the floor */
    pickX = 60 + 70 * (step % 6);
    pickY = windowHeight / 2 + 10 * (step % 3);
    pickPending = 1;
    glutPostRedisplay();
    glutTimerFunc(500, timer, step + 1);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("gluUnProject picking");
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    quadric = gluNewQuadric();
    pickX = 240;
    pickY = 160;
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutTimerFunc(500, timer, 1);
    glutMainLoop();
    return 0;
}
