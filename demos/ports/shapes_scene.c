// A course-style GLUT program drawing GLUT's shapes with gluPerspective; arrows rotate the view.
// Ported to MyGL by changing only the include below (was <GL/glut.h>).
#include <mygl/glut.h>

static float yaw = 30.0f, pitch = 15.0f;

static void display(void) {
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0, 0, -8);
    glRotatef(pitch, 1, 0, 0);
    glRotatef(yaw, 0, 1, 0);
    glPushMatrix();
    glTranslatef(-1.8f, 0, 0);
    glColor3f(0.9f, 0.5f, 0.2f);
    glutSolidTorus(0.4, 1.0, 16, 32);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.8f, 0, 0);
    glColor3f(0.3f, 0.8f, 0.9f);
    glutWireSphere(1.0, 16, 12);
    glPopMatrix();
    glColor3f(0.8f, 0.8f, 0.3f);
    glutSolidCone(0.6, 1.5, 16, 4);
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)width / height, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void special(int key, int x, int y) {
    (void)x, (void)y;
    if (key == GLUT_KEY_LEFT) yaw -= 5;
    if (key == GLUT_KEY_RIGHT) yaw += 5;
    if (key == GLUT_KEY_UP) pitch -= 5;
    if (key == GLUT_KEY_DOWN) pitch += 5;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("GLUT shapes");
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutSpecialFunc(special);
    glutMainLoop();
    return 0;
}
