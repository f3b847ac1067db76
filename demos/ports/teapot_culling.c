/* GLUT's teapot has clockwise front faces, so a program that culls says glFrontFace(GL_CW):
 * left, culled as GLUT intends; right, the back faces only (the inside), in another colour.
 * Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float angle = 20.0f;

static void teapot(float x, GLenum culled, float r, float g, float b) {
    glPushMatrix();
    glTranslatef(x, 0.0f, 0.0f);
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glCullFace(culled);
    glColor3f(r, g, b);
    glutSolidTeapot(1.0);
    glPopMatrix();
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 1.0, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    teapot(-1.7f, GL_BACK, 0.9f, 0.6f, 0.2f);
    teapot(1.7f, GL_FRONT, 0.3f, 0.5f, 0.9f);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void timer(int value) {
    angle += 8.0f;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(400, 240);
    glutCreateWindow("Teapot culling");
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(16, timer, 0);
    glutMainLoop();
    return 0;
}
