/* The Red Book's robot arm: two wire boxes made from scaled cubes, each joint a rotation about
 * its end; 's'/'e' move the shoulder and elbow, and the timer waves the arm. Ported by changing
 * only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static int shoulder = 0, elbow = 0, step = 0;

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    glPushMatrix();
    glTranslatef(-1.0f, 0.0f, 0.0f);
    glRotatef((GLfloat)shoulder, 0.0f, 0.0f, 1.0f);
    glTranslatef(1.0f, 0.0f, 0.0f);
    glPushMatrix();
    glScalef(2.0f, 0.4f, 1.0f);
    glColor3f(1.0f, 0.6f, 0.2f);
    glutWireCube(1.0);
    glPopMatrix();

    glTranslatef(1.0f, 0.0f, 0.0f);
    glRotatef((GLfloat)elbow, 0.0f, 0.0f, 1.0f);
    glTranslatef(1.0f, 0.0f, 0.0f);
    glPushMatrix();
    glScalef(2.0f, 0.4f, 1.0f);
    glColor3f(0.2f, 0.8f, 1.0f);
    glutWireCube(1.0);
    glPopMatrix();

    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(65.0, (GLfloat)w / (GLfloat)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -5.0f);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    switch (key) {
    case 's': shoulder = (shoulder + 5) % 360; break;
    case 'S': shoulder = (shoulder - 5) % 360; break;
    case 'e': elbow = (elbow + 5) % 360; break;
    case 'E': elbow = (elbow - 5) % 360; break;
    case 27: exit(0);
    }
    glutPostRedisplay();
}

static void wave(int value) {
    step++;
    shoulder = (step * 7) % 90 - 45;
    elbow = (step * 11) % 120;
    glutPostRedisplay();
    glutTimerFunc(30, wave, value);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Robot arm");
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glShadeModel(GL_FLAT);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(30, wave, 0);
    glutMainLoop();
    return 0;
}
