/* Quadrics: cylinders, a cone (top radius 0) and a tapered tube drawn with gluCylinder,
 * capped with gluDisk. 'w' toggles wireframe (GLU_LINE), arrows turn the scene. */
#include <mygl/glut.h>
#include <mygl/glu.h>

static GLUquadricObj* quadric;
static float spinX = -60.0f, spinZ = 20.0f;
static int wire = 0;

static void capped(double base, double top, double height) {
    gluCylinder(quadric, base, top, height, 20, 4);
    /* the bottom cap faces -z: turn it round */
    glPushMatrix();
    glRotatef(180.0f, 1.0f, 0.0f, 0.0f);
    gluDisk(quadric, 0.0, base, 20, 2);
    glPopMatrix();
    if (top > 0.0) {
        glPushMatrix();
        glTranslated(0.0, 0.0, height);
        gluDisk(quadric, 0.0, top, 20, 2);
        glPopMatrix();
    }
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gluQuadricDrawStyle(quadric, wire ? GLU_LINE : GLU_FILL);
    glPushMatrix();
    glRotatef(spinX, 1.0f, 0.0f, 0.0f);
    glRotatef(spinZ, 0.0f, 0.0f, 1.0f);

    glColor3f(0.85f, 0.35f, 0.25f);
    glPushMatrix();
    glTranslatef(-1.8f, 0.0f, -0.8f);
    capped(0.6, 0.6, 1.6);
    glPopMatrix();

    glColor3f(0.25f, 0.75f, 0.35f);
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -0.8f);
    capped(0.7, 0.0, 1.8); /* a cone */
    glPopMatrix();

    glColor3f(0.3f, 0.5f, 0.95f);
    glPushMatrix();
    glTranslatef(1.8f, 0.0f, -0.8f);
    capped(0.7, 0.3, 1.4);
    glPopMatrix();

    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)width / (double)height, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -7.0f);
}

static void special(int key, int x, int y) {
    (void)x;
    (void)y;
    if (key == GLUT_KEY_UP) spinX += 5.0f;
    if (key == GLUT_KEY_DOWN) spinX -= 5.0f;
    if (key == GLUT_KEY_LEFT) spinZ -= 5.0f;
    if (key == GLUT_KEY_RIGHT) spinZ += 5.0f;
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'w') wire = !wire;
    glutPostRedisplay();
}

static void timer(int value) {
    spinZ += 6.0f;
    glutPostRedisplay();
    glutTimerFunc(40, timer, value);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("GLU cylinders and cones");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_FLAT);
    quadric = gluNewQuadric();
    gluQuadricNormals(quadric, GLU_FLAT);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutSpecialFunc(special);
    glutTimerFunc(40, timer, 0);
    glutMainLoop();
    return 0;
}
