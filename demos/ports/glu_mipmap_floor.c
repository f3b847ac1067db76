/* Mipmapping with gluBuild2DMipmaps: a checkerboard of 64 x 48 texels (not a power of two:
 * GLU scales it to 64 x 32, then builds every level down to 1 x 1) on a floor receding to the
 * horizon, sampled with GL_LINEAR_MIPMAP_LINEAR so the far squares blend to grey instead of
 * shimmering. 'm' switches to GL_NEAREST for comparison.
 * Needs glTexImage2D, glTexParameteri, glTexEnvi, glBindTexture and GL_TEXTURE_2D. */
#include <mygl/glut.h>
#include <mygl/glu.h>

#define TEX_W 64
#define TEX_H 48

static GLubyte checker[TEX_H][TEX_W][3];
static GLuint texture;
static int mipmapped = 1;
static float scroll = 0.0f;

static void makeChecker(void) {
    int x, y;
    for (y = 0; y < TEX_H; ++y) {
        for (x = 0; x < TEX_W; ++x) {
            const GLubyte c = ((x / 8 + y / 8) % 2) ? 240 : 30;
            checker[y][x][0] = c;
            checker[y][x][1] = c;
            checker[y][x][2] = (GLubyte)(c / 2 + 60);
        }
    }
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glLoadIdentity();
    gluLookAt(0.0, 1.0, 2.0, 0.0, 0.8, -10.0, 0.0, 1.0, 0.0);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, scroll);
    glVertex3f(-4.0f, 0.0f, 2.0f);
    glTexCoord2f(8.0f, scroll);
    glVertex3f(4.0f, 0.0f, 2.0f);
    glTexCoord2f(8.0f, scroll + 40.0f);
    glVertex3f(4.0f, 0.0f, -60.0f);
    glTexCoord2f(0.0f, scroll + 40.0f);
    glVertex3f(-4.0f, 0.0f, -60.0f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (double)width / (double)height, 0.1, 100.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'm') mipmapped = !mipmapped;
    glutPostRedisplay();
}

static void idle(void) {
    scroll += 0.05f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    GLint error;
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("gluBuild2DMipmaps");
    glClearColor(0.55f, 0.7f, 0.9f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    makeChecker();
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    error = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX_W, TEX_H, GL_RGB, GL_UNSIGNED_BYTE, checker);
    if (error) glClearColor(0.6f, 0.1f, 0.1f, 1.0f); /* red sky: gluErrorString(error) says why */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
