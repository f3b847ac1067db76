/* A textured, mipmapped floor under a spinning textured cube, with a heads-up display of
 * bitmap text drawn after it while GL_TEXTURE_2D is still on (the common slip: the text comes
 * out textured, its fragments sampling the bound texture). 't' disables texturing before the
 * text, as the program should; 'm' switches the texture matrix on (a slow scroll of the floor's
 * texture). */
#include <stdio.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

#define TEX_SIZE 32

static GLuint floorTexture;
static int frame = 0;
static int textUntextured = 0;
static int scrolling = 0;

static void makeTexture(void) {
    static GLubyte image[TEX_SIZE][TEX_SIZE][3];
    int i, j;
    for (i = 0; i < TEX_SIZE; i++) {
        for (j = 0; j < TEX_SIZE; j++) {
            const int tile = ((i / 8) + (j / 8)) % 2;
            image[i][j][0] = (GLubyte)(tile ? 220 : 40 + 4 * j);
            image[i][j][1] = (GLubyte)(tile ? 180 : 60 + 3 * i);
            image[i][j][2] = (GLubyte)(tile ? 90 : 200);
        }
    }
    glGenTextures(1, &floorTexture);
    glBindTexture(GL_TEXTURE_2D, floorTexture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX_SIZE, TEX_SIZE, GL_RGB, GL_UNSIGNED_BYTE, image);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void init(void) {
    glClearColor(0.15f, 0.2f, 0.3f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    makeTexture();
}

static void drawFloor(void) {
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-4.0f, -1.0f, 4.0f);
    glTexCoord2f(6.0f, 0.0f);
    glVertex3f(4.0f, -1.0f, 4.0f);
    glTexCoord2f(6.0f, 6.0f);
    glVertex3f(4.0f, -1.0f, -4.0f);
    glTexCoord2f(0.0f, 6.0f);
    glVertex3f(-4.0f, -1.0f, -4.0f);
    glEnd();
}

static void drawCube(void) {
    static const GLfloat v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    int f;
    glBegin(GL_QUADS);
    for (f = 0; f < 6; f++) {
        glColor3f(0.6f + 0.08f * (GLfloat)f, 0.9f - 0.1f * (GLfloat)f, 0.8f);
        glTexCoord2f(0.0f, 0.0f);
        glVertex3fv(v[faces[f][0]]);
        glTexCoord2f(1.0f, 0.0f);
        glVertex3fv(v[faces[f][1]]);
        glTexCoord2f(1.0f, 1.0f);
        glVertex3fv(v[faces[f][2]]);
        glTexCoord2f(0.0f, 1.0f);
        glVertex3fv(v[faces[f][3]]);
    }
    glEnd();
}

static void drawText(GLfloat x, GLfloat y, const char* text) {
    glRasterPos2f(x, y);
    while (*text) glutBitmapCharacter(GLUT_BITMAP_HELVETICA_18, *text++);
}

static void display(void) {
    const int width = glutGet(GLUT_WINDOW_WIDTH), height = glutGet(GLUT_WINDOW_HEIGHT);
    char line[64];
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    if (scrolling) glTranslatef(0.01f * (GLfloat)frame, 0.0f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    drawFloor();
    glPushMatrix();
    glRotatef(20.0f + 7.0f * (GLfloat)frame, 0.3f, 1.0f, 0.1f);
    drawCube();
    glPopMatrix();

    /* The heads-up display: a window-sized orthographic view, no depth test. */
    if (textUntextured) glDisable(GL_TEXTURE_2D);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluOrtho2D(0.0, (GLdouble)width, 0.0, (GLdouble)height);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1.0f, 0.95f, 0.4f);
    sprintf(line, "frame %d", frame);
    drawText(10.0f, (GLfloat)height - 24.0f, line);
    glColor3f(0.7f, 1.0f, 0.7f);
    drawText(10.0f, 12.0f, textUntextured ? "text: untextured" : "text: textured (GL_TEXTURE_2D on)");
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_TEXTURE_2D);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (GLdouble)w / (GLdouble)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void idle(void) {
    frame++;
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 't') textUntextured = !textUntextured;
    if (key == 'm') scrolling = !scrolling;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("textured_hud");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
