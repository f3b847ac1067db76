/* Compositing into a pre-rendered background, as course programs do it with pixel rectangles:
 * a lit scene (floor and spheres) is rendered once, its colours and depths saved with
 * glReadPixels; every frame restores both with glDrawPixels (the depths with colour writes off)
 * and draws a spinning torus into it, hidden where the background is nearer. A round stencil
 * mask drawn from an image (glDrawPixels of GL_STENCIL_INDEX) tints the frame outside a
 * "spotlight", and glCopyPixels copies a corner's depths and stencil values to the other side. */
#include <stdlib.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

static int width = 1, height = 1;
static GLubyte* backgroundColor = NULL;
static GLfloat* backgroundDepth = NULL;
static GLubyte* spotMask = NULL;
static GLfloat angle = 0.0f;

static void perspectiveView(void) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)width / (GLdouble)height, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void windowView(void) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (GLdouble)width, 0.0, (GLdouble)height, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* The background, rendered once per size and saved. */
static void renderBackground(void) {
    static const GLfloat colors[3][4] = {{0.8f, 0.2f, 0.2f, 1.0f}, {0.2f, 0.7f, 0.3f, 1.0f}, {0.3f, 0.4f, 0.9f, 1.0f}};
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    perspectiveView();
    glEnable(GL_LIGHTING);
    glColor3f(0.6f, 0.6f, 0.5f);
    glNormal3f(0.0f, 1.0f, 0.0f);
    glBegin(GL_QUADS);
    glVertex3f(-4.0f, -1.0f, 4.0f);
    glVertex3f(4.0f, -1.0f, 4.0f);
    glVertex3f(4.0f, -1.0f, -4.0f);
    glVertex3f(-4.0f, -1.0f, -4.0f);
    glEnd();
    for (i = 0; i < 3; i++) {
        glPushMatrix();
        glTranslatef(-1.6f + 1.6f * (GLfloat)i, -0.3f, (GLfloat)(i % 2) * 0.8f - 0.4f);
        glColor4fv(colors[i]);
        glutSolidSphere(0.7, 20, 14);
        glPopMatrix();
    }
    glDisable(GL_LIGHTING);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, backgroundColor);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, backgroundDepth);
}

/* A filled circle of stencil 1 in a field of 0, as big as the window. */
static void makeSpotMask(void) {
    int x, y;
    const int radius = (width < height ? width : height) / 3;
    for (y = 0; y < height; y++) {
        for (x = 0; x < width; x++) {
            const int dx = x - width / 2, dy = y - height / 2;
            spotMask[y * width + x] = (GLubyte)(dx * dx + dy * dy <= radius * radius ? 1 : 0);
        }
    }
}

static void init(void) {
    static const GLfloat lightPosition[] = {2.0f, 4.0f, 3.0f, 0.0f};
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glClearStencil(0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    windowView();
    glRasterPos2i(0, 0);
    /* The saved colours, then the saved depths with colour writes off and every depth written. */
    glDisable(GL_DEPTH_TEST);
    glDrawPixels(width, height, GL_RGBA, GL_UNSIGNED_BYTE, backgroundColor);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDrawPixels(width, height, GL_DEPTH_COMPONENT, GL_FLOAT, backgroundDepth);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
    /* The spotlight's stencil mask. */
    glDrawPixels(width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, spotMask);

    /* The torus, into the background's depths. */
    perspectiveView();
    glEnable(GL_LIGHTING);
    glPushMatrix();
    glTranslatef(0.0f, 0.1f, 0.3f);
    glRotatef(angle, 0.3f, 1.0f, 0.2f);
    glColor3f(0.95f, 0.75f, 0.2f);
    glutSolidTorus(0.25, 1.3, 16, 32);
    glPopMatrix();
    glDisable(GL_LIGHTING);

    /* Outside the spotlight, a dark tint. */
    windowView();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.0f, 0.0f, 0.1f, 0.5f);
    glRecti(0, 0, width, height);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);

    /* The lower-left corner's depths and stencil values copied to the lower right, zoomed,
     * then shown: grey where the copied depths lie nearer than 0.9. */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glColor3f(0.9f, 0.9f, 0.9f);
    glPixelZoom(1.5f, 1.5f);
    glRasterPos2i(width - width / 4 - width / 8, 0);
    glCopyPixels(0, 0, width / 4, height / 4, GL_DEPTH);
    glCopyPixels(width / 3, height / 3, width / 4, height / 4, GL_STENCIL);
    glPixelZoom(1.0f, 1.0f);
    glDepthFunc(GL_LESS);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    width = w > 0 ? w : 1;
    height = h > 0 ? h : 1;
    free(backgroundColor);
    free(backgroundDepth);
    free(spotMask);
    backgroundColor = (GLubyte*)malloc((size_t)width * (size_t)height * 4);
    backgroundDepth = (GLfloat*)malloc((size_t)width * (size_t)height * sizeof(GLfloat));
    spotMask = (GLubyte*)malloc((size_t)width * (size_t)height);
    renderBackground();
    makeSpotMask();
}

static void idle(void) {
    angle += 7.0f;
    if (angle >= 360.0f) angle -= 360.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(240, 180);
    glutCreateWindow("depth_composite");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
