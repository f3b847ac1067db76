/* The Sierpinski gasket by the chaos game, as Angel's textbook draws it: thousands of points,
 * each halfway from the last one to a random corner; every frame adds more. Ported by changing
 * only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static const GLfloat corners[3][2] = {{0.0f, 0.0f}, {250.0f, 500.0f}, {500.0f, 0.0f}};
static GLfloat p[2] = {75.0f, 50.0f};
static int points = 0;

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    srand(1);
    p[0] = 75.0f;
    p[1] = 50.0f;
    points += 4000;
    glBegin(GL_POINTS);
    for (i = 0; i < points; i++) {
        int j = rand() % 3;
        p[0] = (p[0] + corners[j][0]) / 2.0f;
        p[1] = (p[1] + corners[j][1]) / 2.0f;
        glColor3f(p[0] / 500.0f, p[1] / 500.0f, 0.6f);
        glVertex2fv(p);
    }
    glEnd();
    glFlush();
}

static void idle(void) { glutPostRedisplay(); }

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(300, 300);
    glutCreateWindow("Sierpinski gasket");
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 500.0, 0.0, 500.0);
    glMatrixMode(GL_MODELVIEW);
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
