/* What glutGet, glutDeviceGet and glutLayerGet report about the window, printed into it with
 * a fixed-width font, one query a line. Ported by changing only the include. */
#include <stdio.h>
#include <mygl/glut.h>

static void line(int row, const char* name, int value) {
    char text[64];
    sprintf(text, "%-24s %d", name, value);
    glRasterPos2i(10, glutGet(GLUT_WINDOW_HEIGHT) - 20 - 16 * row);
    glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char*)text);
}

static void display(void) {
    int row = 0;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.6f, 1.0f, 0.6f);
    line(row++, "GLUT_WINDOW_WIDTH", glutGet(GLUT_WINDOW_WIDTH));
    line(row++, "GLUT_WINDOW_HEIGHT", glutGet(GLUT_WINDOW_HEIGHT));
    line(row++, "GLUT_WINDOW_DEPTH_SIZE", glutGet(GLUT_WINDOW_DEPTH_SIZE));
    line(row++, "GLUT_WINDOW_RED_SIZE", glutGet(GLUT_WINDOW_RED_SIZE));
    line(row++, "GLUT_WINDOW_DOUBLEBUFFER", glutGet(GLUT_WINDOW_DOUBLEBUFFER));
    line(row++, "GLUT_WINDOW_RGBA", glutGet(GLUT_WINDOW_RGBA));
    line(row++, "GLUT_DISPLAY_MODE_POSSIBLE", glutGet(GLUT_DISPLAY_MODE_POSSIBLE));
    glColor3f(0.6f, 0.8f, 1.0f);
    line(row++, "GLUT_HAS_KEYBOARD", glutDeviceGet(GLUT_HAS_KEYBOARD));
    line(row++, "GLUT_HAS_MOUSE", glutDeviceGet(GLUT_HAS_MOUSE));
    line(row++, "GLUT_NUM_MOUSE_BUTTONS", glutDeviceGet(GLUT_NUM_MOUSE_BUTTONS));
    line(row++, "GLUT_OVERLAY_POSSIBLE", glutLayerGet(GLUT_OVERLAY_POSSIBLE));
    line(row++, "GLUT_LAYER_IN_USE", glutLayerGet(GLUT_LAYER_IN_USE));
    line(row++, "glutGetWindow", glutGetWindow());
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, w, 0.0, h);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH | GLUT_STENCIL | GLUT_ACCUM | GLUT_MULTISAMPLE);
    glutInitWindowSize(340, 240);
    glutCreateWindow("Window information");
    glutSetWindowTitle("glutGet");
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
