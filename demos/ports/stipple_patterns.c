/* Stipple patterns in the style of the Red Book's lines.c and polys.c: stippled lines of several
 * patterns and repeat factors (single lines, a strip, a wide line, a smooth-coloured loop), and
 * two polygons filled through the fly and halftone stipples beside a plain one; the third frame
 * also draws a polygon's edges in GL_LINE mode under the line stipple. Ported by changing only
 * the include (was <GL/glut.h>). */
#include <math.h>
#include <mygl/glut.h>

static int frame = 0;

static const GLubyte fly[] = {
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x03, 0x80, 0x01, 0xC0, 0x06, 0xC0, 0x03, 0x60, 0x04, 0x60, 0x06,
    0x20, 0x04, 0x30, 0x0C, 0x20, 0x04, 0x18, 0x18, 0x20, 0x04, 0x0C, 0x30, 0x20, 0x04, 0x06, 0x60, 0x20, 0x44, 0x03,
    0xC0, 0x22, 0x44, 0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22, 0x44,
    0x01, 0x80, 0x22, 0x44, 0x01, 0x80, 0x22, 0x66, 0x01, 0x80, 0x66, 0x33, 0x01, 0x80, 0xCC, 0x19, 0x81, 0x81, 0x98,
    0x0C, 0xC1, 0x83, 0x30, 0x07, 0xe1, 0x87, 0xe0, 0x03, 0x3f, 0xfc, 0xc0, 0x03, 0x31, 0x8c, 0xc0, 0x03, 0x33, 0xcc,
    0xc0, 0x06, 0x64, 0x26, 0x60, 0x0c, 0xcc, 0x33, 0x30, 0x18, 0xcc, 0x33, 0x18, 0x10, 0xc4, 0x23, 0x08, 0x10, 0x63,
    0xC6, 0x08, 0x10, 0x30, 0x0c, 0x08, 0x10, 0x18, 0x18, 0x08, 0x10, 0x00, 0x00, 0x08};

static GLubyte halftone[128];

static void drawOneLine(float x1, float y1, float x2, float y2) {
    glBegin(GL_LINES);
    glVertex2f(x1, y1);
    glVertex2f(x2, y2);
    glEnd();
}

static void lines(void) {
    int i;
    glColor3f(1.0f, 1.0f, 1.0f);
    glEnable(GL_LINE_STIPPLE);
    /* first row: three patterns */
    glLineStipple(1, 0x0101); /* dotted */
    drawOneLine(50.0f, 275.0f, 150.0f, 275.0f + (float)frame);
    glLineStipple(1, 0x00FF); /* dashed */
    drawOneLine(150.0f, 275.0f, 250.0f, 275.0f);
    glLineStipple(1, 0x1C47); /* dash/dot/dash */
    drawOneLine(250.0f, 275.0f, 350.0f, 275.0f - (float)frame);
    /* second row: a wide line */
    glLineWidth(5.0f);
    glLineStipple(1, 0x0101);
    drawOneLine(50.0f, 255.0f, 150.0f, 255.0f);
    glLineStipple(1, 0x00FF);
    drawOneLine(150.0f, 255.0f, 250.0f, 255.0f);
    glLineWidth(1.0f);
    /* third row: a strip of six segments, one pattern running through it */
    glLineStipple(1, 0x1C47);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i < 7; i++) glVertex2f(50.0f + 50.0f * (float)i, 235.0f + 6.0f * (float)(i % 2));
    glEnd();
    /* fourth row: six independent lines, each restarting the pattern */
    for (i = 0; i < 6; i++) drawOneLine(50.0f + 50.0f * (float)i, 215.0f, 50.0f + 50.0f * (float)(i + 1), 215.0f);
    /* fifth row: repeat factor 5 */
    glLineStipple(5, 0x1C47);
    drawOneLine(50.0f, 195.0f, 350.0f, 195.0f);
    /* a smooth-coloured loop */
    glLineStipple(2, 0x3F07);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 5; i++) {
        float a = 2.0f * 3.14159265f * (float)i / 5.0f + 0.1f * (float)frame;
        glColor3f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 1.0f);
        glVertex2f(340.0f + 40.0f * cosf(a), 100.0f + 40.0f * sinf(a));
    }
    glEnd();
    glDisable(GL_LINE_STIPPLE);
}

static void polys(void) {
    glColor3f(1.0f, 1.0f, 1.0f);
    glRectf(25.0f, 25.0f, 125.0f, 125.0f);
    glEnable(GL_POLYGON_STIPPLE);
    glColor3f(1.0f, 0.8f, 0.2f);
    glPolygonStipple(fly);
    glRectf(125.0f, 25.0f, 225.0f, 125.0f);
    glColor3f(0.3f, 0.7f, 1.0f);
    glPolygonStipple(halftone);
    glBegin(GL_TRIANGLES);
    glVertex2f(225.0f, 25.0f);
    glVertex2f(295.0f, 40.0f + (float)frame);
    glColor3f(1.0f, 0.3f, 0.5f);
    glVertex2f(250.0f, 150.0f);
    glEnd();
    glDisable(GL_POLYGON_STIPPLE);
    if (frame >= 2) {
        /* a polygon's edges, stippled, the pattern restarting at the polygon */
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(3, 0x0F0F);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glColor3f(0.2f, 1.0f, 0.4f);
        glBegin(GL_POLYGON);
        glVertex2f(30.0f, 140.0f);
        glVertex2f(200.0f, 140.0f);
        glVertex2f(215.0f, 180.0f);
        glVertex2f(40.0f, 185.0f);
        glEnd();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_LINE_STIPPLE);
    }
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT);
    lines();
    polys();
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

static void timer(int value) {
    frame = value;
    glutPostRedisplay();
    glutTimerFunc(16, timer, value + 1);
}

int main(int argc, char** argv) {
    int i;
    for (i = 0; i < 128; i++) halftone[i] = (GLubyte)(((i / 4) % 2) ? 0x55 : 0xAA);
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Stipple patterns");
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glShadeModel(GL_SMOOTH);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(16, timer, 1);
    glutMainLoop();
    return 0;
}
