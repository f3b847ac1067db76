// A course-style GLUT program: a depth-tested 3D scene with a 2D head-up display drawn over it.
// The HUD saves the state it changes with glPushAttrib/glPushClientAttrib and the matrix stacks,
// and gives it back with the pops, so the next frame's scene finds the depth test, its polygon
// modes and its viewport as it left them. 'w' toggles the scene's wireframe. Ported to MyGL by
// changing only the include below (was <GL/glut.h>).
#include <mygl/glut.h>

static float angle = 15.0f;
static int wireframe = 0, frames = 0;
static int windowWidth = 320, windowHeight = 240;

static void pyramid(float size) {
    static const float colors[4][3] = {{0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f}};
    const float apex[3] = {0.0f, size, 0.0f};
    const float base[4][3] = {{-size, -size, size}, {size, -size, size}, {size, -size, -size}, {-size, -size, -size}};
    int i;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 4; ++i) {
        glColor3fv(colors[i]);
        glVertex3fv(apex);
        glVertex3fv(base[i]);
        glVertex3fv(base[(i + 1) % 4]);
    }
    glEnd();
}

static void scene(void) {
    glPolygonMode(GL_FRONT_AND_BACK, wireframe ? GL_LINE : GL_FILL);
    glLoadIdentity();
    gluLookAt(0.0, 1.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glPushMatrix();
    glTranslatef(-1.2f, 0.0f, 0.0f);
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    pyramid(1.0f);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.0f, -0.2f, -1.0f);
    glRotatef(-2.0f * angle, 0.2f, 1.0f, 0.0f);
    pyramid(1.2f);
    glPopMatrix();
}

// The HUD in window pixels: a panel, a bar, a crosshair and a caption, over everything.
static void hud(void) {
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_POLYGON_BIT | GL_LINE_BIT | GL_DEPTH_BUFFER_BIT |
                 GL_TRANSFORM_BIT | GL_VIEWPORT_BIT);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glViewport(0, 0, windowWidth, windowHeight);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluOrtho2D(0.0, windowWidth, 0.0, windowHeight);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();

    glColor3f(0.15f, 0.15f, 0.2f);
    glRectf(8.0f, 8.0f, 168.0f, 44.0f);
    glColor3f(0.2f, 0.9f, 0.3f);
    glRectf(14.0f, 14.0f, 14.0f + 1.5f * (float)(60 + (frames * 7) % 40), 22.0f);
    glLineWidth(2.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINES);
    glVertex2f(windowWidth / 2.0f - 8.0f, windowHeight / 2.0f);
    glVertex2f(windowWidth / 2.0f + 8.0f, windowHeight / 2.0f);
    glVertex2f(windowWidth / 2.0f, windowHeight / 2.0f - 8.0f);
    glVertex2f(windowWidth / 2.0f, windowHeight / 2.0f + 8.0f);
    glEnd();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1.0f, 0.9f, 0.4f);
    glRasterPos2i(14, 28);
    glutBitmapString(GLUT_BITMAP_8_BY_13, (const unsigned char*)"HUD: push/pop");

    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glPopClientAttrib();
    glPopAttrib();  // back to GL_MODELVIEW, the depth test on, the scene's polygon mode
}

static void display(void) {
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene();
    hud();
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    windowWidth = width;
    windowHeight = height;
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)width / height, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    if (key == 'w') wireframe = !wireframe;
    glutPostRedisplay();
}

static void idle(void) {
    angle += 4.0f;  // the display changes every frame: compare mode replays the same calls
    ++frames;
    if (frames % 2 == 0) wireframe = !wireframe;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("HUD over a 3D scene");
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_SMOOTH);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
