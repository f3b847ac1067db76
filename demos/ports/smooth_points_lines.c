/* Antialiased points and lines (the Red Book's aargb.c style): GL_LINE_SMOOTH and
 * GL_POINT_SMOOTH blended over a dark background, two crossed lines rotating, a wheel of thin
 * and wide spokes with a colour per vertex, round points of sizes 1 to 12 and a stippled smooth
 * loop. Ported by changing only the include (was <GL/glut.h>). */
#include <math.h>
#include <mygl/glut.h>

static float rotAngle = 0.0f;

static void init(void) {
    GLfloat values[2];
    glGetFloatv(GL_LINE_WIDTH_GRANULARITY, values);
    glGetFloatv(GL_LINE_WIDTH_RANGE, values);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glHint(GL_LINE_SMOOTH_HINT, GL_DONT_CARE);
    glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
    glLineWidth(1.5f);
    glClearColor(0.05f, 0.05f, 0.12f, 1.0f);
}

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT);

    glColor3f(0.0f, 1.0f, 0.0f);
    glPushMatrix();
    glTranslatef(100.0f, 200.0f, 0.0f);
    glRotatef(-rotAngle, 0.0f, 0.0f, 0.1f);
    glBegin(GL_LINES);
    glVertex2f(-50.0f, 50.0f);
    glVertex2f(50.0f, -50.0f);
    glEnd();
    glPopMatrix();

    glColor3f(0.0f, 0.0f, 1.0f);
    glPushMatrix();
    glTranslatef(100.0f, 200.0f, 0.0f);
    glRotatef(rotAngle, 0.0f, 0.0f, 0.1f);
    glBegin(GL_LINES);
    glVertex2f(50.0f, 50.0f);
    glVertex2f(-50.0f, -50.0f);
    glEnd();
    glPopMatrix();

    for (i = 0; i < 12; i++) {
        float a = 2.0f * 3.14159265f * (float)i / 12.0f + 0.01f * rotAngle;
        glLineWidth(1.0f + 0.5f * (float)(i % 6));
        glBegin(GL_LINES);
        glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
        glVertex2f(290.0f, 200.0f);
        glColor4f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.3f, 0.6f);
        glVertex2f(290.0f + 70.0f * cosf(a), 200.0f + 70.0f * sinf(a));
        glEnd();
    }

    for (i = 1; i <= 12; i++) {
        glPointSize((GLfloat)i);
        glBegin(GL_POINTS);
        glColor4f(1.0f, 0.9f - 0.06f * (float)i, 0.2f, 0.9f);
        glVertex2f(15.0f + 30.0f * (float)i + 0.3f * (float)(i % 3), 80.0f + 0.25f * (float)i);
        glEnd();
    }

    glLineWidth(2.0f);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(3, 0x3F07);
    glColor4f(1.0f, 0.5f, 0.8f, 0.8f);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 5; i++) {
        float a = 2.0f * 3.14159265f * (float)i / 5.0f + 0.02f * rotAngle;
        glVertex2f(200.0f + 150.0f * cosf(a), 40.0f + 25.0f * sinf(a));
    }
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glLineWidth(1.5f);

    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (GLdouble)w, 0.0, (GLdouble)h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'r' || key == 'R') {
        rotAngle += 20.0f;
        if (rotAngle >= 360.0f) rotAngle = 0.0f;
        glutPostRedisplay();
    }
}

static void timer(int value) {
    rotAngle += 7.0f;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value + 1);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Antialiased points and lines");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(16, timer, 1);
    glutMainLoop();
    return 0;
}
