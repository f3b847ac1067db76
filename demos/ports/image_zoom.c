/* An image program in the Red Book's style (image.c): a 64 x 64 checkerboard shaded by a
 * colour gradient, made in the program, drawn with glDrawPixels at the lower left; glPixelZoom
 * grows it frame by frame (or follows the mouse while a button is held); glCopyPixels copies
 * the image's lower-left quarter to the right, mirrored by a negative zoom, and a small part of
 * the image onto itself, overlapping. A grey bar in front of the image shows the depth test
 * at the raster position's depth. */
#include <mygl/glut.h>
#include <mygl/glu.h>

#define IMAGE_W 64
#define IMAGE_H 64

static GLubyte image[IMAGE_H][IMAGE_W][4];
static GLint windowHeight = 1;
static GLfloat zoomFactor = 1.0f;
static int frame = 0;
static int dragging = 0;

static void makeImage(void) {
    int i, j;
    for (i = 0; i < IMAGE_H; i++) {
        for (j = 0; j < IMAGE_W; j++) {
            const int check = ((i & 0x8) == 0) ^ ((j & 0x8) == 0);
            image[i][j][0] = (GLubyte)(check ? 255 : j * 4);
            image[i][j][1] = (GLubyte)(check ? i * 4 : 40);
            image[i][j][2] = (GLubyte)(check ? 128 : 255 - i * 4);
            image[i][j][3] = 255;
        }
    }
}

static void init(void) {
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    makeImage();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    /* A bar in front of part of the image (z = 0.5 against the image's 0). */
    glColor3f(0.6f, 0.6f, 0.6f);
    glBegin(GL_QUADS);
    glVertex3f(0.0f, 90.0f, 0.5f);
    glVertex3f(250.0f, 90.0f, 0.5f);
    glVertex3f(250.0f, 100.0f, 0.5f);
    glVertex3f(0.0f, 100.0f, 0.5f);
    glEnd();
    glPixelZoom(zoomFactor, zoomFactor);
    glRasterPos3f(4.0f, 4.0f, -0.5f);
    glDrawPixels(IMAGE_W, IMAGE_H, GL_RGBA, GL_UNSIGNED_BYTE, image);
    /* The lower-left quarter, mirrored left to right and stretched upwards. */
    glPixelZoom(-1.5f, 2.0f);
    glRasterPos2i(240, 120);
    glCopyPixels(4, 4, 32, 32, GL_COLOR);
    /* The image's top band copied onto itself, shifted up and right: the rectangles overlap. */
    glPixelZoom(1.0f, 1.0f);
    glRasterPos2i(20, 70);
    glCopyPixels(4, 60, 60, 40, GL_COLOR);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    windowHeight = (GLint)h;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (GLdouble)w, 0.0, (GLdouble)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void motion(int x, int y) {
    /* Zoom by the distance from the lower-left corner. */
    const GLint screeny = windowHeight - (GLint)y;
    zoomFactor = (GLfloat)(x + screeny) / 128.0f + 0.25f;
    glutPostRedisplay();
}

static void mouse(int button, int state, int x, int y) {
    if (button != GLUT_LEFT_BUTTON) return;
    dragging = state == GLUT_DOWN;
    if (dragging) motion(x, y);
}

static void idle(void) {
    if (dragging) return;
    frame++;
    zoomFactor = 1.0f + 0.35f * (GLfloat)(frame % 6);
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'r') zoomFactor = 1.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(250, 250);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("image_zoom");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
