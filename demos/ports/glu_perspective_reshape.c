/* Viewing: the reshape callback keeps the picture undistorted with gluPerspective(fovy, aspect)
 * whatever the window's shape, and '+' / '-' change the field of view: a corridor of cubes
 * recedes to the horizon. */
#include <mygl/glut.h>
#include <mygl/glu.h>

static double fovy = 60.0;
static int windowWidth = 480, windowHeight = 300;

static void cube(void) {
    static const GLfloat v[8][3] = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, -0.5f},
                                    {-0.5f, 0.5f, -0.5f},  {-0.5f, -0.5f, 0.5f}, {0.5f, -0.5f, 0.5f},
                                    {0.5f, 0.5f, 0.5f},    {-0.5f, 0.5f, 0.5f}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    static const GLfloat shade[6] = {1.0f, 0.5f, 0.8f, 0.7f, 0.9f, 0.4f};
    int f, i;
    GLfloat color[4];
    glGetFloatv(GL_CURRENT_COLOR, color);
    glBegin(GL_QUADS);
    for (f = 0; f < 6; ++f) {
        glColor3f(color[0] * shade[f], color[1] * shade[f], color[2] * shade[f]);
        for (i = 0; i < 4; ++i) glVertex3fv(v[faces[f][i]]);
    }
    glEnd();
    glColor3fv(color);
}

static void setProjection(void) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(fovy, (double)windowWidth / (double)windowHeight, 0.5, 100.0);
    glMatrixMode(GL_MODELVIEW);
}

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    setProjection();
    glLoadIdentity();
    gluLookAt(0.0, 1.0, 3.0, 0.0, 0.6, -10.0, 0.0, 1.0, 0.0);
    for (i = 0; i < 12; ++i) {
        glPushMatrix();
        glTranslatef(-1.5f, 0.5f, -2.5f * (float)i);
        glColor3f(0.9f, 0.4f, 0.3f);
        cube();
        glTranslatef(3.0f, 0.0f, 0.0f);
        glColor3f(0.3f, 0.6f, 0.9f);
        cube();
        glPopMatrix();
    }
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    windowWidth = width;
    windowHeight = height > 0 ? height : 1;
    glViewport(0, 0, windowWidth, windowHeight);
    setProjection();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == '+' && fovy > 15.0) fovy -= 5.0;
    if (key == '-' && fovy < 120.0) fovy += 5.0;
    glutPostRedisplay();
}

static void idle(void) {
    fovy = fovy >= 100.0 ? 30.0 : fovy + 10.0; /* zoom out step by step, then start again */
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(windowWidth, windowHeight);
    glutCreateWindow("gluPerspective and reshape");
    glClearColor(0.6f, 0.75f, 0.9f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
