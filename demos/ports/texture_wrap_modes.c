/* Texture wrap modes, as a course shows them: one 8 x 8 texture on three squares whose
 * coordinates run from -0.5 to 1.5, wrapped with GL_REPEAT, GL_CLAMP (its blue border colour
 * blended in at the edges under GL_LINEAR) and GL_CLAMP_TO_EDGE, in GL_DECAL over coloured
 * squares, tilting away from the viewer a little more each frame. 'f' switches between
 * GL_LINEAR and GL_NEAREST, 'b' cycles the border colour. */
#include <mygl/glut.h>
#include <mygl/glu.h>

#ifndef GL_CLAMP_TO_EDGE /* GL 1.2, absent from GL 1.1 headers */
#define GL_CLAMP_TO_EDGE 0x812F
#endif
#define SIDE 8

static GLubyte image[SIDE][SIDE][4];
static GLuint texName;
static int nearest = 0;
static int borderIndex = 0;
static float tilt = 20.0f;
static const GLfloat borders[3][4] = {{0.1f, 0.3f, 0.9f, 1.0f}, {1.0f, 0.8f, 0.0f, 0.5f}, {0.0f, 0.0f, 0.0f, 0.0f}};

static void makeImage(void) {
    int i, j;
    for (i = 0; i < SIDE; i++) {
        for (j = 0; j < SIDE; j++) {
            const int on = (i + j) % 2 == 0;
            image[i][j][0] = (GLubyte)(on ? 240 : 30 * j);
            image[i][j][1] = (GLubyte)(on ? 200 : 255 - 30 * i);
            image[i][j][2] = (GLubyte)(40 + 20 * i);
            image[i][j][3] = (GLubyte)(on ? 255 : 120);
        }
    }
}

static void init(void) {
    glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    makeImage();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &texName);
    glBindTexture(GL_TEXTURE_2D, texName);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, SIDE, SIDE, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
}

static void square(GLenum wrap, float x) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap);
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.2f, 0.2f);
    glTexCoord2f(-0.5f, -0.5f);
    glVertex3f(x - 0.9f, -0.9f, 0.0f);
    glColor3f(0.2f, 0.9f, 0.2f);
    glTexCoord2f(1.5f, -0.5f);
    glVertex3f(x + 0.9f, -0.9f, 0.0f);
    glColor3f(0.9f, 0.9f, 0.9f);
    glTexCoord2f(1.5f, 1.5f);
    glVertex3f(x + 0.9f, 0.9f, 0.0f);
    glColor3f(0.2f, 0.2f, 0.9f);
    glTexCoord2f(-0.5f, 1.5f);
    glVertex3f(x - 0.9f, 0.9f, 0.0f);
    glEnd();
}

static void display(void) {
    const GLint filter = nearest ? GL_NEAREST : GL_LINEAR;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(-tilt, 1.0f, 0.0f, 0.0f);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texName);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, borders[borderIndex]);
    square(GL_REPEAT, -2.0f);
    square(GL_CLAMP, 0.0f);
    square(GL_CLAMP_TO_EDGE, 2.0f);
    glDisable(GL_TEXTURE_2D);
    glPopMatrix();
    glutSwapBuffers();
}

static void idle(void) {
    tilt += 15.0f;
    if (tilt > 70.0f) tilt = 20.0f;
    glutPostRedisplay();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (GLfloat)w / (GLfloat)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.5f);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'f') nearest = !nearest;
    if (key == 'b') borderIndex = (borderIndex + 1) % 3;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(360, 160);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("texture_wrap_modes");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
