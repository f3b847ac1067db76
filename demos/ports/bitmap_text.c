/* Text over a 3D scene with GLUT's bitmap fonts: a spinning wire cube in perspective, then a
 * 2D overlay in window coordinates with every bitmap font, glutBitmapString, glutBitmapLength
 * for centring and a frame counter. Ported by changing only the include (was <GL/glut.h>). */
#include <stdio.h>
#include <string.h>
#include <mygl/glut.h>

static int width = 400, height = 300;
static float angle = 0.0f;
static int frame = 0;

static void drawString(void* font, float x, float y, const char* text) {
    glRasterPos2f(x, y);
    while (*text) glutBitmapCharacter(font, *text++);
}

static void display(void) {
    char line[64];
    const unsigned char* title = (const unsigned char*)"Centred with glutBitmapLength";
    int length;

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)width / height, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.4f, 0.8f, 1.0f);
    glutWireCube(2.0);

    /* The overlay: window coordinates, no depth test. */
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, width, 0, height);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glColor3f(1.0f, 1.0f, 0.0f);
    drawString(GLUT_BITMAP_8_BY_13, 10, height - 20, "8x13: The quick brown fox");
    glColor3f(1.0f, 0.5f, 0.0f);
    drawString(GLUT_BITMAP_9_BY_15, 10, height - 40, "9x15: jumps over the lazy dog");
    glColor3f(0.8f, 0.8f, 0.8f);
    drawString(GLUT_BITMAP_TIMES_ROMAN_10, 10, height - 60, "Times Roman 10");
    drawString(GLUT_BITMAP_TIMES_ROMAN_24, 10, height - 90, "Times Roman 24");
    glColor3f(0.5f, 1.0f, 0.5f);
    drawString(GLUT_BITMAP_HELVETICA_10, 10, 70, "Helvetica 10");
    drawString(GLUT_BITMAP_HELVETICA_12, 10, 50, "Helvetica 12");
    drawString(GLUT_BITMAP_HELVETICA_18, 10, 26, "Helvetica 18");

    length = glutBitmapLength(GLUT_BITMAP_HELVETICA_12, title);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRasterPos2i((width - length) / 2, height / 2);
    glutBitmapString(GLUT_BITMAP_HELVETICA_12, title);

    sprintf(line, "frame %d\nline two", frame);
    glRasterPos2i(width - 100, 40);
    glutBitmapString(GLUT_BITMAP_8_BY_13, (const unsigned char*)line);

    glutSwapBuffers();
}

static void reshape(int w, int h) {
    width = w;
    height = h;
    glViewport(0, 0, w, h);
}

static void idle(void) {
    angle += 2.0f;
    frame++;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(width, height);
    glutCreateWindow("Bitmap fonts");
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
