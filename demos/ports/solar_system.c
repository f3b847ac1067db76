/* The Red Book's planet program, animated: a sun and a planet with its moon as wire spheres,
 * matrices pushed and popped per body, the year and day advanced by a timer; 'd'/'y' step them
 * by hand. Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static int year = 0, day = 0;

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1.0f, 0.9f, 0.2f);
    glPushMatrix();
    glutWireSphere(1.0, 20, 16); /* the sun */
    glRotatef((GLfloat)year, 0.0f, 1.0f, 0.0f);
    glTranslatef(2.0f, 0.0f, 0.0f);
    glRotatef((GLfloat)day, 0.0f, 1.0f, 0.0f);
    glColor3f(0.3f, 0.6f, 1.0f);
    glutWireSphere(0.2, 10, 8); /* the planet */
    glRotatef((GLfloat)(day * 2), 0.0f, 1.0f, 0.0f);
    glTranslatef(0.5f, 0.0f, 0.0f);
    glColor3f(0.8f, 0.8f, 0.8f);
    glutSolidSphere(0.07, 8, 6); /* its moon */
    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (GLfloat)w / (GLfloat)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    switch (key) {
    case 'd': day = (day + 10) % 360; break;
    case 'D': day = (day - 10) % 360; break;
    case 'y': year = (year + 5) % 360; break;
    case 'Y': year = (year - 5) % 360; break;
    case 27: exit(0);
    }
    glutPostRedisplay();
}

static void timer(int value) {
    day = (day + 10) % 360;
    year = (year + 2) % 360;
    glutPostRedisplay();
    glutTimerFunc(20, timer, value + 1);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(400, 300);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("Planets");
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(20, timer, 0);
    glutMainLoop();
    return 0;
}
