/* The modelling program's four views: top, front and side in orthographic projection and a
 * perspective view, each in its own glViewport, labelled with a bitmap font. Ported by
 * changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static int width = 400, height = 400;
static float angle = 0.0f;

static void scene(void) {
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    glColor3f(0.9f, 0.9f, 0.5f);
    glutWireTeapot(0.8);
    glColor3f(0.4f, 0.7f, 1.0f);
    glTranslatef(0.0f, -0.6f, 0.0f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glutWireTorus(0.05, 1.3, 4, 24);
}

static void label(const char* text) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 1.0, 0.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1.0f, 1.0f, 1.0f);
    glRasterPos2f(0.03f, 0.92f);
    glutBitmapString(GLUT_BITMAP_HELVETICA_12, (const unsigned char*)text);
}

static void view(int column, int row, int perspective, float rx, float ry, const char* name) {
    int w = width / 2, h = height / 2;
    glViewport(column * w, row * h, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (perspective)
        gluPerspective(40.0, (double)w / h, 1.0, 20.0);
    else
        glOrtho(-2.0, 2.0, -2.0, 2.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    if (perspective) gluLookAt(3.0, 2.5, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(rx, 1.0f, 0.0f, 0.0f);
    glRotatef(ry, 0.0f, 1.0f, 0.0f);
    scene();
    label(name);
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    view(0, 1, 0, 90.0f, 0.0f, "Top");
    view(1, 1, 0, 0.0f, 0.0f, "Front");
    view(0, 0, 0, 0.0f, 90.0f, "Side");
    view(1, 0, 1, 0.0f, 0.0f, "Perspective");
    glViewport(0, 0, width, height);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    width = w;
    height = h;
}

static void idle(void) {
    angle += 3.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(width, height);
    glutCreateWindow("Four views");
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
