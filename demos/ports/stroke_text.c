/* GLUT's stroke fonts: text drawn as lines in model space, so it scales and rotates like any
 * geometry. Roman and Mono Roman, glutStrokeLength to centre, glutStrokeString with a newline.
 * Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static float spin = 0.0f;

static void strokeText(void* font, const char* text) {
    while (*text) glutStrokeCharacter(font, *text++);
}

static void display(void) {
    const unsigned char* banner = (const unsigned char*)"GLUT";
    float length = (float)glutStrokeLength(GLUT_STROKE_ROMAN, banner);

    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glPushMatrix();
    glTranslatef(200.0f, 200.0f, 0.0f);
    glRotatef(spin, 0.0f, 0.0f, 1.0f);
    glScalef(0.6f, 0.6f, 1.0f);
    glTranslatef(-length / 2.0f, -50.0f, 0.0f);
    glColor3f(1.0f, 0.8f, 0.2f);
    glLineWidth(2.0f);
    glutStrokeString(GLUT_STROKE_ROMAN, banner);
    glLineWidth(1.0f);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(10.0f, 60.0f, 0.0f);
    glScalef(0.15f, 0.15f, 1.0f);
    glColor3f(0.6f, 1.0f, 0.6f);
    strokeText(GLUT_STROKE_MONO_ROMAN, "Mono Roman 0123456789");
    glPopMatrix();

    glPushMatrix();
    glTranslatef(10.0f, 30.0f, 0.0f);
    glScalef(0.12f, 0.12f, 1.0f);
    glColor3f(0.6f, 0.8f, 1.0f);
    glutStrokeString(GLUT_STROKE_ROMAN, (const unsigned char*)"Roman: two lines\nof stroke text");
    glPopMatrix();

    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 400.0, 0.0, 300.0);
}

static void timer(int value) {
    spin += 5.0f;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Stroke fonts");
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(16, timer, 0);
    glutMainLoop();
    return 0;
}
