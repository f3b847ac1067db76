/* GLUT's solids filled, without lighting: each drawn in its colour with back faces culled and
 * the depth test on, a wire outline of each drawn a little larger around it. Ported by
 * changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float angle = 30.0f;

static void solid(float x, float y, float r, float g, float b, void (*draw)(void)) {
    glPushMatrix();
    glTranslatef(x, y, 0.0f);
    glRotatef(angle, 0.2f, 1.0f, 0.3f);
    glColor3f(r, g, b);
    draw();
    glScalef(1.08f, 1.08f, 1.08f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    draw();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPopMatrix();
}

static void cube(void) { glutSolidCube(1.3); }
static void sphere(void) { glutSolidSphere(0.8, 16, 12); }
static void cone(void) { glutSolidCone(0.7, 1.3, 14, 3); }
static void torus(void) { glutSolidTorus(0.25, 0.65, 10, 20); }
static void cylinder(void) { glutSolidCylinder(0.6, 1.1, 14, 2); }
static void rhombic(void) { glutSolidRhombicDodecahedron(); }

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -8.0f);
    solid(-2.4f, 1.2f, 0.8f, 0.2f, 0.2f, cube);
    solid(0.0f, 1.2f, 0.2f, 0.7f, 0.3f, sphere);
    solid(2.4f, 1.2f, 0.2f, 0.3f, 0.8f, cone);
    solid(-2.4f, -1.2f, 0.8f, 0.7f, 0.1f, torus);
    solid(0.0f, -1.2f, 0.6f, 0.2f, 0.7f, cylinder);
    solid(2.4f, -1.2f, 0.1f, 0.7f, 0.7f, rhombic);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void idle(void) {
    angle += 5.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("Solid solids");
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
