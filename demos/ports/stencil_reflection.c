/* A planar reflection with the stencil buffer, in the style of Kilgard's dinoshade and the red
 * book's stencil examples: the floor is drawn into the stencil buffer only (colour and depth
 * masked), the object is drawn mirrored below the floor where the stencil is 1, then the floor
 * is blended over the reflection and the object drawn upright. A scissored strip at the bottom
 * shows the stencil test inverted (the mirror image outside the floor is kept out). Ported by
 * changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float angle = 20.0f;

static void floorQuad(void) {
    glBegin(GL_QUADS);
    glVertex3f(-2.0f, 0.0f, 3.2f);
    glVertex3f(2.0f, 0.0f, 3.2f);
    glVertex3f(2.0f, 0.0f, -2.0f);
    glVertex3f(-2.0f, 0.0f, -2.0f);
    glEnd();
}

static void object(void) {
    const GLfloat gold[] = {0.85f, 0.65f, 0.2f, 1.0f}, blue[] = {0.2f, 0.35f, 0.9f, 1.0f};
    glPushMatrix();
    glTranslatef(0.0f, 0.9f, 0.0f);
    glRotatef(angle, 0.3f, 1.0f, 0.0f);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
    glutSolidTorus(0.2, 0.55, 12, 24);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    glutSolidCube(0.45);
    glPopMatrix();
}

static void display(void) {
    const GLfloat light[] = {1.0f, 3.0f, 2.0f, 0.0f};
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 2.2, 5.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);

    /* 1: the floor into the stencil buffer only. */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    floorQuad();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);

    /* 2: the reflection where the floor is. */
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glPushMatrix();
    glScalef(1.0f, -1.0f, 1.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glFrontFace(GL_CW);
    glEnable(GL_LIGHTING);
    object();
    glDisable(GL_LIGHTING);
    glFrontFace(GL_CCW);
    glPopMatrix();
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glDisable(GL_STENCIL_TEST);

    /* 3: the floor blended over its reflection, then the object itself. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.55f, 0.6f, 0.7f, 0.6f);
    floorQuad();
    glDisable(GL_BLEND);
    glEnable(GL_LIGHTING);
    object();
    glDisable(GL_LIGHTING);

    /* 4: a strip along the bottom shows where the stencil is not 1, in a flat tint. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 480, 40);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glColor3f(0.3f, 0.1f, 0.1f);
    glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
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
    angle += 13.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(480, 360);
    glutCreateWindow("Stencil reflection");
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClearStencil(0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
