/* User clip planes in the style of the red book's clip.c: a wire sphere cut by two planes
 * (keep y < 0, keep x > 0), beside a lit solid torus sliced by a plane that turns with it, so
 * its inside shows. Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float angle = 30.0f;

static void display(void) {
    static const GLdouble belowY[] = {0.0, -1.0, 0.0, 0.0}, rightOfX[] = {1.0, 0.0, 0.0, 0.0};
    static const GLdouble slice[] = {0.3, 0.2, -1.0, 0.1};

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);

    glPushMatrix();
    glTranslatef(-1.4f, 0.0f, 0.0f);
    glClipPlane(GL_CLIP_PLANE0, belowY);
    glClipPlane(GL_CLIP_PLANE1, rightOfX);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    glColor3f(0.9f, 0.9f, 0.4f);
    glutWireSphere(1.0, 20, 16);
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE1);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(1.4f, 0.0f, 0.0f);
    glRotatef(angle, 0.2f, 1.0f, 0.0f);
    glClipPlane(GL_CLIP_PLANE2, slice);
    glEnable(GL_CLIP_PLANE2);
    glEnable(GL_LIGHTING);
    glutSolidTorus(0.35, 0.8, 16, 32);
    glDisable(GL_LIGHTING);
    glDisable(GL_CLIP_PLANE2);
    glPopMatrix();
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
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    static const GLfloat lightPosition[] = {1.0f, 2.0f, 3.0f, 0.0f};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(400, 240);
    glutCreateWindow("Clip planes");
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
