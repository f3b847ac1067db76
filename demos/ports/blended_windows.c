/* Transparent coloured windows in front of a lit scene, in the style of the red book's
 * alpha3D.c: a lit sphere and a solid cube are drawn first with depth writes, then four
 * glass panes with GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA blending, sorted back to front each
 * frame and drawn with the depth mask off, so panes behind the solids are hidden but panes never
 * hide each other. The panes turn around the scene. Ported by changing only the include (was
 * <GL/glut.h>). */
#include <math.h>
#include <stdlib.h>

#include <mygl/glut.h>

#define PANES 4

static float angle = 15.0f;

static const float paneColor[PANES][4] = {
    {0.9f, 0.2f, 0.2f, 0.45f}, {0.2f, 0.8f, 0.3f, 0.35f}, {0.2f, 0.4f, 0.95f, 0.55f}, {0.95f, 0.85f, 0.2f, 0.3f}};

struct Pane {
    int index;
    float depth; /* eye-space z of its centre */
};

static int fartherFirst(const void* a, const void* b) {
    const struct Pane* p = a;
    const struct Pane* q = b;
    return p->depth < q->depth ? -1 : p->depth > q->depth ? 1 : 0;
}

static void paneCentre(int i, float* x, float* z) {
    const float a = (angle + 90.0f * (float)i) * 3.14159265f / 180.0f;
    *x = 1.6f * cosf(a);
    *z = 1.6f * sinf(a);
}

static void solids(void) {
    const GLfloat red[] = {0.8f, 0.2f, 0.15f, 1.0f}, grey[] = {0.35f, 0.35f, 0.4f, 1.0f};
    glEnable(GL_LIGHTING);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    glutSolidSphere(0.7, 24, 16);
    glPushMatrix();
    glTranslatef(0.0f, -1.3f, 0.0f);
    glScalef(3.0f, 0.3f, 3.0f);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    glutSolidCube(1.0);
    glPopMatrix();
    glDisable(GL_LIGHTING);
}

static void display(void) {
    struct Pane panes[PANES];
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, -0.2f, -6.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    solids();
    /* Sort the panes back to front: eye z after the view's rotation about x, then translation. */
    for (i = 0; i < PANES; ++i) {
        float x, z;
        paneCentre(i, &x, &z);
        panes[i].index = i;
        panes[i].depth = z * cosf(20.0f * 3.14159265f / 180.0f) - 6.0f;
    }
    qsort(panes, PANES, sizeof panes[0], fartherFirst);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE); /* panes are seen from both sides */
    for (i = 0; i < PANES; ++i) {
        float x, z;
        const int p = panes[i].index;
        paneCentre(p, &x, &z);
        glPushMatrix();
        glTranslatef(x, 0.0f, z);
        glRotatef(-(angle + 90.0f * (float)p), 0.0f, 1.0f, 0.0f);
        glColor4fv(paneColor[p]);
        glBegin(GL_QUADS);
        glVertex3f(0.0f, -1.0f, -0.9f);
        glVertex3f(0.0f, -1.0f, 0.9f);
        glVertex3f(0.0f, 1.0f, 0.9f);
        glVertex3f(0.0f, 1.0f, -0.9f);
        glEnd();
        glPopMatrix();
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
}

static void idle(void) {
    angle += 11.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    const GLfloat position[] = {2.0f, 4.0f, 3.0f, 0.0f};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
    glutInitWindowSize(480, 360);
    glutCreateWindow("Blended windows");
    glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE); /* the floor is a scaled cube */
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_CULL_FACE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
