/* Hidden-line rendering with polygon offset, in the style of the red book's polyoff.c: a
 * turning torus and a wavy grid drawn filled and pushed back by glPolygonOffset, then drawn
 * again as lines in a dark colour on the same surfaces, so that the edges win the depth test
 * without stitching. The offset is switched between the fill and the lines each frame (as the
 * original's keys do). Ported by changing only the include (was <GL/glut.h>). */
#include <math.h>

#include <mygl/glut.h>

static float angle = 30.0f;
static int offsetLines = 0;

static void grid(void) {
    int i, j;
    for (i = 0; i < 12; ++i) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= 12; ++j) {
            float x0 = -3.0f + 0.5f * (float)i, x1 = x0 + 0.5f, z = -3.0f + 0.5f * (float)j;
            glVertex3f(x0, 0.2f * sinf(x0 + z), z);
            glVertex3f(x1, 0.2f * sinf(x1 + z), z);
        }
        glEnd();
    }
}

static void scene(void) {
    glPushMatrix();
    glTranslatef(0.0f, -1.2f, 0.0f);
    grid();
    glPopMatrix();
    glPushMatrix();
    glRotatef(angle, 1.0f, 0.4f, 0.0f);
    glutSolidTorus(0.35, 0.9, 12, 18);
    glPopMatrix();
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 5.5, 0.0, -0.3, 0.0, 0.0, 1.0, 0.0);
    /* The surfaces, pushed back (or the lines pulled forward). */
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColor3f(0.75f, 0.8f, 0.9f);
    if (!offsetLines) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
    }
    scene();
    glDisable(GL_POLYGON_OFFSET_FILL);
    /* The same surfaces as lines. */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(0.1f, 0.15f, 0.3f);
    if (offsetLines) {
        glEnable(GL_POLYGON_OFFSET_LINE);
        glPolygonOffset(-1.0f, -1.0f);
    }
    scene();
    glDisable(GL_POLYGON_OFFSET_LINE);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
}

static void idle(void) {
    angle += 9.0f;
    offsetLines = !offsetLines;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("Polygon offset decals");
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
