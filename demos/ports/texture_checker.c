/* The Red Book's checkerboard: a 64 x 64 black and white checker texture, made in the program,
 * on two squares: one facing the viewer, one turned 45 degrees away from it so that the texture
 * shows in perspective. GL_NEAREST filters, GL_REPEAT wraps, GL_DECAL; a texture object bound
 * once. 't' cycles the environment (DECAL, MODULATE, REPLACE) over a coloured square, 'f'
 * switches to GL_LINEAR. */
#include <mygl/glut.h>
#include <mygl/glu.h>

#define CHECK_W 64
#define CHECK_H 64

static GLubyte checkImage[CHECK_H][CHECK_W][4];
static GLuint texName;
static int envIndex = 0;
static int linear = 0;
static const GLenum envModes[] = {GL_DECAL, GL_MODULATE, GL_REPLACE};

static void makeCheckImage(void) {
    int i, j;
    for (i = 0; i < CHECK_H; i++) {
        for (j = 0; j < CHECK_W; j++) {
            const GLubyte c = (GLubyte)((((i & 0x8) == 0) ^ ((j & 0x8) == 0)) * 255);
            checkImage[i][j][0] = c;
            checkImage[i][j][1] = c;
            checkImage[i][j][2] = c;
            checkImage[i][j][3] = 255;
        }
    }
}

static void init(void) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    makeCheckImage();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &texName);
    glBindTexture(GL_TEXTURE_2D, texName);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, CHECK_W, CHECK_H, 0, GL_RGBA, GL_UNSIGNED_BYTE, checkImage);
}

static void display(void) {
    const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLfloat)envModes[envIndex]);
    glBindTexture(GL_TEXTURE_2D, texName);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glColor3f(0.9f, 0.6f, 0.3f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-2.0f, -1.0f, 0.0f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex3f(-2.0f, 1.0f, 0.0f);
    glTexCoord2f(1.0f, 1.0f);
    glVertex3f(0.0f, 1.0f, 0.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(0.0f, -1.0f, 0.0f);

    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(1.0f, -1.0f, 0.0f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex3f(1.0f, 1.0f, 0.0f);
    glTexCoord2f(1.0f, 1.0f);
    glVertex3f(2.41421f, 1.0f, -1.41421f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(2.41421f, -1.0f, -1.41421f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (GLfloat)w / (GLfloat)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.6f);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 't') envIndex = (envIndex + 1) % 3;
    if (key == 'f') linear = !linear;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(250, 250);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("texture_checker");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
