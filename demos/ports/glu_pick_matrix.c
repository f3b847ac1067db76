/* Picking with gluPickMatrix and the selection buffer: a click redraws the scene in GL_SELECT
 * mode through a 5 x 5 pixel pick matrix, each object named with glLoadName; the nearest hit is
 * highlighted. Headless, a click on the third sphere is simulated.
 * Uses glSelectBuffer, glRenderMode, glInitNames, glPushName and glLoadName. */
#include <mygl/glut.h>
#include <mygl/glu.h>

#define BUFSIZE 64

static GLUquadricObj* quadric;
static int selected = -1;
static int clickX = 285, clickY = 160, clickPending = 1; /* over the third sphere */

static void setProjection(int picking, int x, int y) {
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (picking) gluPickMatrix((GLdouble)x, (GLdouble)(viewport[3] - y), 5.0, 5.0, viewport);
    gluPerspective(45.0, (double)viewport[2] / (double)viewport[3], 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void drawObjects(GLenum mode) {
    int i;
    for (i = 0; i < 4; ++i) {
        if (mode == GL_SELECT) glLoadName((GLuint)i);
        glPushMatrix();
        glTranslatef(-2.4f + 1.6f * (float)i, 0.0f, 0.0f);
        if (i == selected)
            glColor3f(1.0f, 0.9f, 0.2f);
        else
            glColor3f(0.3f + 0.15f * (float)i, 0.4f, 0.8f - 0.15f * (float)i);
        gluSphere(quadric, 0.6, 16, 12);
        glPopMatrix();
    }
}

static void pick(int x, int y) {
    GLuint buffer[BUFSIZE];
    GLint hits, i;
    GLuint nearest = 0xffffffffu, *record = buffer;
    glSelectBuffer(BUFSIZE, buffer);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(0);
    setProjection(1, x, y);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -7.0f);
    drawObjects(GL_SELECT);
    hits = glRenderMode(GL_RENDER);
    selected = -1;
    for (i = 0; i < hits; ++i) { /* names, zmin, zmax, name... */
        if (record[1] < nearest) {
            nearest = record[1];
            selected = (int)record[3];
        }
        record += 3 + record[0];
    }
    setProjection(0, 0, 0);
}

static void display(void) {
    if (clickPending) {
        pick(clickX, clickY);
        clickPending = 0;
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -7.0f);
    drawObjects(GL_RENDER);
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    setProjection(0, 0, 0);
}

static void mouse(int button, int state, int x, int y) {
    if (button != GLUT_LEFT_BUTTON || state != GLUT_DOWN) return;
    clickX = x;
    clickY = y;
    clickPending = 1;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("gluPickMatrix selection");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    quadric = gluNewQuadric();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutMainLoop();
    return 0;
}
