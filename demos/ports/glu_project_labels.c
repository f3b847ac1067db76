/* gluProject: the window positions of a rotating tetrahedron's corners, computed with
 * gluProject from the current matrices, are marked in a 2D overlay drawn with gluOrtho2D
 * (boxes around each corner and a bounding rectangle of the projected shape). */
#include <mygl/glut.h>
#include <mygl/glu.h>

static const GLdouble corners[4][3] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
static float angle = 10.0f;

static void display(void) {
    static const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    static const float colors[4][3] = {{0.9f, 0.3f, 0.3f}, {0.3f, 0.9f, 0.3f}, {0.3f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f}};
    GLdouble model[16], proj[16], window[4][3];
    GLdouble left = 1e9, right = -1e9, bottom = 1e9, top = -1e9;
    GLint viewport[4];
    int f, i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glGetIntegerv(GL_VIEWPORT, viewport);
    gluPerspective(40.0, (double)viewport[2] / (double)viewport[3], 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);
    glRotatef(angle, 0.3f, 1.0f, 0.2f);
    glBegin(GL_TRIANGLES);
    for (f = 0; f < 4; ++f) {
        glColor3fv(colors[f]);
        for (i = 0; i < 3; ++i) glVertex3dv(corners[faces[f][i]]);
    }
    glEnd();

    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    for (i = 0; i < 4; ++i) {
        gluProject(corners[i][0], corners[i][1], corners[i][2], model, proj, viewport, &window[i][0], &window[i][1],
                   &window[i][2]);
        if (window[i][0] < left) left = window[i][0];
        if (window[i][0] > right) right = window[i][0];
        if (window[i][1] < bottom) bottom = window[i][1];
        if (window[i][1] > top) top = window[i][1];
    }

    /* the overlay, in window coordinates */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, viewport[2], 0.0, viewport[3]);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glColor3f(1.0f, 1.0f, 1.0f);
    for (i = 0; i < 4; ++i) {
        glBegin(GL_LINE_LOOP);
        glVertex2d(window[i][0] - 6, window[i][1] - 6);
        glVertex2d(window[i][0] + 6, window[i][1] - 6);
        glVertex2d(window[i][0] + 6, window[i][1] + 6);
        glVertex2d(window[i][0] - 6, window[i][1] + 6);
        glEnd();
    }
    glColor3f(0.5f, 0.9f, 1.0f);
    glBegin(GL_LINE_LOOP);
    glVertex2d(left, bottom);
    glVertex2d(right, bottom);
    glVertex2d(right, top);
    glVertex2d(left, top);
    glEnd();
    glEnable(GL_DEPTH_TEST);
    glutSwapBuffers();
}

static void reshape(int width, int height) { glViewport(0, 0, width, height); }

static void idle(void) {
    angle += 7.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(360, 300);
    glutCreateWindow("gluProject labels");
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
