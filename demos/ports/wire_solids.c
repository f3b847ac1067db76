/* Every GLUT solid in wire frame on a grid, turning together: cube, sphere, cone, torus,
 * tetrahedron, octahedron, dodecahedron, icosahedron, rhombic dodecahedron, cylinder, teapot
 * and a Sierpinski sponge. Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float angle = 10.0f;

static void place(int column, int row) {
    glLoadIdentity();
    glTranslatef(-4.5f + 3.0f * (float)column, 3.0f - 3.0f * (float)row, -12.0f);
    glRotatef(angle, 1.0f, 1.0f, 0.0f);
}

static void display(void) {
    double offset[3] = {0.0, 0.0, 0.0};
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 1.0f);
    place(0, 0);
    glutWireCube(1.4);
    place(1, 0);
    glutWireSphere(0.9, 12, 8);
    place(2, 0);
    glutWireCone(0.8, 1.4, 12, 4);
    place(3, 0);
    glutWireTorus(0.25, 0.7, 8, 16);
    glColor3f(0.5f, 1.0f, 0.5f);
    place(0, 1);
    glutWireTetrahedron();
    place(1, 1);
    glutWireOctahedron();
    place(2, 1);
    glScalef(0.55f, 0.55f, 0.55f);
    glutWireDodecahedron();
    place(3, 1);
    glutWireIcosahedron();
    glColor3f(1.0f, 0.6f, 0.4f);
    place(0, 2);
    glutWireRhombicDodecahedron();
    place(1, 2);
    glutWireCylinder(0.6, 1.2, 12, 3);
    place(2, 2);
    glutWireTeapot(0.8);
    place(3, 2);
    glutWireSierpinskiSponge(2, offset, 1.0);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / h, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
}

static void timer(int value) {
    angle += 6.0f;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 360);
    glutCreateWindow("Wire solids");
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(16, timer, 0);
    glutMainLoop();
    return 0;
}
