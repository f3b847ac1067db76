// A course-style GLUT program: a rotating cube with back-face culling, 'b' toggles culling and
// 'w' wireframe. Ported to MyGL by changing only the include below (was <GL/glut.h>).
#include <mygl/glut.h>

static float angle = 20.0f;
static int culling = 1, wireframe = 0;

static void display(void) {
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (culling)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, wireframe ? GL_LINE : GL_FILL);
    glLoadIdentity();
    gluLookAt(0, 1.5, 5, 0, 0, 0, 0, 1, 0);
    glRotatef(angle, 0.3f, 1.0f, 0.1f);
    static const float colors[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
    static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    glBegin(GL_QUADS);
    int f, i;
    for (f = 0; f < 6; ++f) {
        glColor3fv(colors[f]);
        for (i = 0; i < 4; ++i) glVertex3fv(v[faces[f][i]]);
    }
    glEnd();
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)width / height, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    if (key == 'b') culling = !culling;
    if (key == 'w') wireframe = !wireframe;
    glutPostRedisplay();
}

static void idle(void) {
    angle += 3.0f;  // the display changes every frame: compare mode replays the same calls
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("cube with culling");
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
