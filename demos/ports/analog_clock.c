/* An analog clock driven by glutGet(GLUT_ELAPSED_TIME), hands drawn with wide lines, ticks
 * with points, the time printed in Helvetica. Headless the clock runs at 16 ms a frame.
 * Ported by changing only the include (was <GL/glut.h>). */
#include <math.h>
#include <stdio.h>
#include <mygl/glut.h>

static void hand(float turns, float length, float width) {
    float a = 3.14159265f / 2.0f - 2.0f * 3.14159265f * turns;
    glLineWidth(width);
    glBegin(GL_LINES);
    glVertex2f(0.0f, 0.0f);
    glVertex2f(length * cosf(a), length * sinf(a));
    glEnd();
}

static void display(void) {
    int i;
    long ms = (long)glutGet(GLUT_ELAPSED_TIME) * 1000L + 10L * 3600L * 1000L + 8L * 60L * 1000L;
    float seconds = (float)(ms % 60000) / 1000.0f;
    float minutes = (float)(ms % 3600000) / 60000.0f;
    float hours = (float)(ms % 43200000) / 3600000.0f;
    char text[32];

    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 1.0f);
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 12; i++) glVertex2f(0.85f * cosf(0.5236f * (float)i), 0.85f * sinf(0.5236f * (float)i));
    glEnd();
    glColor3f(0.8f, 0.8f, 1.0f);
    hand(hours / 12.0f, 0.45f, 5.0f);
    hand(minutes / 60.0f, 0.7f, 3.0f);
    glColor3f(1.0f, 0.3f, 0.3f);
    hand(seconds / 60.0f, 0.8f, 1.0f);
    glLineWidth(1.0f);

    sprintf(text, "%02d:%02d:%02d", (int)hours, (int)minutes, (int)seconds);
    glColor3f(1.0f, 1.0f, 0.4f);
    glRasterPos2f(-0.3f, -0.97f);
    glutBitmapString(GLUT_BITMAP_HELVETICA_18, (const unsigned char*)text);
    glutSwapBuffers();
}

static void idle(void) { glutPostRedisplay(); }

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(260, 260);
    glutCreateWindow("Clock");
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
