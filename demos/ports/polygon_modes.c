/* glPolygonMode: the same torus as points, lines and filled, front and back faces in different
 * modes, with 'p' cycling the point size. Ported by changing only the include. */
#include <mygl/glut.h>

static float angle = 0.0f;
static float pointSize = 2.0f;

static void torusAt(float x, GLenum front, GLenum back) {
    glPushMatrix();
    glTranslatef(x, 0.0f, 0.0f);
    glRotatef(angle, 1.0f, 0.5f, 0.0f);
    glPolygonMode(GL_FRONT, front);
    glPolygonMode(GL_BACK, back);
    glutSolidTorus(0.3, 0.8, 10, 18);
    glPopMatrix();
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -7.0f);
    glPointSize(pointSize);
    glColor3f(1.0f, 0.3f, 0.3f);
    torusAt(-2.3f, GL_POINT, GL_POINT);
    glColor3f(0.3f, 1.0f, 0.3f);
    torusAt(0.0f, GL_LINE, GL_LINE);
    glColor3f(0.3f, 0.5f, 1.0f);
    torusAt(2.3f, GL_FILL, GL_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    if (key == 'p') pointSize = pointSize >= 4.0f ? 1.0f : pointSize + 1.0f;
    glutPostRedisplay();
}

static void timer(int value) {
    angle += 7.0f;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 240);
    glutCreateWindow("Polygon modes");
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(16, timer, 0);
    glutMainLoop();
    return 0;
}
