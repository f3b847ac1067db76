/* Quadrics: one sphere in each GLU draw style (fill, line, silhouette, point), spinning.
 * Keys: 'o' toggles GLU_OUTSIDE / GLU_INSIDE, '+' / '-' change the slices and stacks. */
#include <mygl/glut.h>
#include <mygl/glu.h>

static GLUquadricObj* quadric;
static float angle = 15.0f;
static int slices = 16, stacks = 10;
static GLenum orientation = GLU_OUTSIDE;

static void display(void) {
    static const GLenum styles[4] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
    static const float colors[4][3] = {{0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.3f, 0.5f, 1.0f}, {1.0f, 0.9f, 0.2f}};
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gluQuadricOrientation(quadric, orientation);
    for (i = 0; i < 4; ++i) {
        glPushMatrix();
        glTranslatef(i % 2 ? 1.3f : -1.3f, i < 2 ? 1.1f : -1.1f, 0.0f);
        glRotatef(angle, 0.2f, 1.0f, 0.0f);
        glRotatef(-90.0f, 1.0f, 0.0f, 0.0f); /* GLU's poles lie on z: stand the sphere up */
        gluQuadricDrawStyle(quadric, styles[i]);
        glColor3fv(colors[i]);
        gluSphere(quadric, 0.9, slices, stacks);
        glPopMatrix();
    }
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)width / (double)height, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 7.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'o') orientation = orientation == GLU_OUTSIDE ? GLU_INSIDE : GLU_OUTSIDE;
    if (key == '+' && slices < 64) {
        slices += 2;
        stacks += 1;
    }
    if (key == '-' && stacks > 3) {
        slices -= 2;
        stacks -= 1;
    }
    glutPostRedisplay();
}

static void idle(void) {
    angle += 4.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(400, 400);
    glutCreateWindow("GLU sphere draw styles");
    glClearColor(0.08f, 0.08f, 0.12f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glPointSize(2.0f);
    quadric = gluNewQuadric();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    gluDeleteQuadric(quadric);
    return 0;
}
