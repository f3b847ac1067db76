/* Lit spheres and a teapot with materials, in the style of the red book's light.c and
 * material.c: one positional white light and a directional blue one, diffuse, specular
 * (several shininess values), emission and colour-material objects, smooth shaded with the
 * depth test on. Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float angle = 20.0f;

static void materialSphere(float x, float y, const GLfloat* diffuse, const GLfloat* specular, float shininess,
                           const GLfloat* emission) {
    glPushMatrix();
    glTranslatef(x, y, 0.0f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, shininess);
    glMaterialfv(GL_FRONT, GL_EMISSION, emission);
    glutSolidSphere(0.7, 24, 16);
    glPopMatrix();
}

static void display(void) {
    static const GLfloat noMat[] = {0.0f, 0.0f, 0.0f, 1.0f};
    static const GLfloat red[] = {0.8f, 0.2f, 0.2f, 1.0f}, green[] = {0.2f, 0.7f, 0.3f, 1.0f};
    static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f}, glow[] = {0.3f, 0.2f, 0.0f, 1.0f};
    static const GLfloat lightPosition[] = {2.0f, 3.0f, 4.0f, 1.0f};
    static const GLfloat blueDirection[] = {-1.0f, -0.5f, 0.5f, 0.0f};

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 0.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, blueDirection);

    glPushMatrix();
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    materialSphere(-2.0f, 1.0f, red, noMat, 0.0f, noMat);
    materialSphere(0.0f, 1.0f, red, white, 5.0f, noMat);
    materialSphere(2.0f, 1.0f, red, white, 100.0f, noMat);
    materialSphere(-2.0f, -1.0f, green, white, 30.0f, glow);
    glPopMatrix();

    /* A teapot coloured through glColorMaterial. */
    glMaterialfv(GL_FRONT, GL_EMISSION, noMat);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.9f, 0.7f, 0.2f);
    glPushMatrix();
    glTranslatef(1.2f, -1.0f, 0.0f);
    glRotatef(angle, 0.3f, 1.0f, 0.0f);
    glutSolidTeapot(0.6);
    glPopMatrix();
    glDisable(GL_COLOR_MATERIAL);
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
    angle += 7.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f}, blue[] = {0.2f, 0.3f, 0.9f, 1.0f};
    static const GLfloat ambient[] = {0.15f, 0.15f, 0.15f, 1.0f};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("Lit materials");
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
