/* A keyboard-driven viewer: arrows orbit the camera, +/- zoom, 'w' toggles wireframe, 'c'
 * culling, ESC quits; keys released and special keys released are reported too. Headless it
 * shows the initial view each frame. Ported by changing only the include. */
#include <mygl/glut.h>

static double yaw = 30.0, pitch = 20.0, distance = 7.0;
static int wireframe = 0, culling = 1;
static int keysDown = 0;

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslated(0.0, 0.0, -distance);
    glRotated(pitch, 1.0, 0.0, 0.0);
    glRotated(yaw, 0.0, 1.0, 0.0);

    if (culling)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, wireframe ? GL_LINE : GL_FILL);

    glColor3f(0.9f, 0.3f, 0.3f);
    glPushMatrix();
    glTranslatef(-1.5f, 0.0f, 0.0f);
    glutSolidOctahedron();
    glPopMatrix();

    glColor3f(0.3f, 0.9f, 0.4f);
    glPushMatrix();
    glTranslatef(1.5f, 0.0f, 0.0f);
    glutSolidIcosahedron();
    glPopMatrix();

    glColor3f(0.4f, 0.5f, 1.0f);
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -1.8f);
    glScalef(0.6f, 0.6f, 0.6f);
    glutSolidDodecahedron();
    glPopMatrix();

    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 0.5, 50.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    keysDown++;
    switch (key) {
    case '+': distance -= 0.5; break;
    case '-': distance += 0.5; break;
    case 'w': wireframe = !wireframe; break;
    case 'c': culling = !culling; break;
    case 27: exit(0);
    }
    glutPostRedisplay();
}

static void keyboardUp(unsigned char key, int x, int y) {
    (void)key, (void)x, (void)y;
    keysDown--;
}

static void special(int key, int x, int y) {
    (void)x, (void)y;
    if (key == GLUT_KEY_LEFT) yaw -= 5.0;
    if (key == GLUT_KEY_RIGHT) yaw += 5.0;
    if (key == GLUT_KEY_UP) pitch -= 5.0;
    if (key == GLUT_KEY_DOWN) pitch += 5.0;
    if (key == GLUT_KEY_PAGE_UP) distance -= 1.0;
    if (key == GLUT_KEY_PAGE_DOWN) distance += 1.0;
    glutPostRedisplay();
}

static void specialUp(int key, int x, int y) { (void)key, (void)x, (void)y; }

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH | GLUT_ALPHA);
    glutInitWindowSize(360, 270);
    glutCreateWindow("Keyboard viewer");
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
    glutIgnoreKeyRepeat(1);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(keyboardUp);
    glutSpecialFunc(special);
    glutSpecialUpFunc(specialUp);
    glutMainLoop();
    return 0;
}
