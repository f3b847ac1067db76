/* Viewing: a camera orbiting a small scene with gluLookAt (eye on a circle, looking at the
 * centre). Arrows change the orbit's angle and height, 'a' stops the automatic orbit. */
#include <math.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

#define PI 3.14159265358979323846

static GLUquadricObj* quadric;
static double azimuth = 30.0, height = 2.0, distance = 7.0;
static int animate = 1;

static void grid(void) {
    int i;
    glColor3f(0.35f, 0.35f, 0.4f);
    glBegin(GL_LINES);
    for (i = -5; i <= 5; ++i) {
        glVertex3f((float)i, 0.0f, -5.0f);
        glVertex3f((float)i, 0.0f, 5.0f);
        glVertex3f(-5.0f, 0.0f, (float)i);
        glVertex3f(5.0f, 0.0f, (float)i);
    }
    glEnd();
}

static void display(void) {
    const double a = azimuth * PI / 180.0;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(distance * sin(a), height, distance * cos(a), 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
    grid();
    glPushMatrix(); /* a column: a cylinder standing on the floor (GLU's axis is z) */
    glTranslatef(-1.5f, 0.0f, 0.0f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glColor3f(0.8f, 0.5f, 0.3f);
    gluCylinder(quadric, 0.4, 0.4, 2.0, 16, 1);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.2f, 0.8f, 0.5f);
    glColor3f(0.3f, 0.6f, 0.9f);
    gluSphere(quadric, 0.8, 18, 12);
    glPopMatrix();
    glPushMatrix(); /* a cone */
    glTranslatef(0.0f, 0.0f, -1.8f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glColor3f(0.4f, 0.8f, 0.4f);
    gluCylinder(quadric, 0.7, 0.0, 1.6, 16, 1);
    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)width / (double)height, 0.5, 50.0);
    glMatrixMode(GL_MODELVIEW);
}

static void special(int key, int x, int y) {
    (void)x;
    (void)y;
    if (key == GLUT_KEY_LEFT) azimuth -= 5.0;
    if (key == GLUT_KEY_RIGHT) azimuth += 5.0;
    if (key == GLUT_KEY_UP) height += 0.25;
    if (key == GLUT_KEY_DOWN) height -= 0.25;
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'a') animate = !animate;
    if (key == '+') distance -= 0.5;
    if (key == '-') distance += 0.5;
    glutPostRedisplay();
}

static void idle(void) {
    if (!animate) return;
    azimuth += 3.0;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 360);
    glutCreateWindow("gluLookAt orbit");
    glClearColor(0.05f, 0.07f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    quadric = gluNewQuadric();
    gluQuadricDrawStyle(quadric, GLU_LINE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutSpecialFunc(special);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
