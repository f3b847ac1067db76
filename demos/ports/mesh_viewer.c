/* A vertex-array mesh viewer as a course assignment writes one: a height-field mesh built once
 * into an interleaved colour + position array and an index array, drawn each frame with
 * glInterleavedArrays and glDrawElements; the idle callback turns it, 'w' toggles wireframe.
 * Ported by changing only the include. */
#include <mygl/glut.h>
#include <math.h>

#define GRID 48
#define VERTICES ((GRID + 1) * (GRID + 1))

static GLfloat mesh[VERTICES][6]; /* r, g, b, x, y, z: GL_C3F_V3F */
static GLushort indices[GRID * GRID * 6];
static GLfloat angle = 0.0f;
static int wireframe = 0;

static void buildMesh(void) {
    int i, j, k = 0;
    for (j = 0; j <= GRID; ++j) {
        for (i = 0; i <= GRID; ++i) {
            GLfloat* v = mesh[j * (GRID + 1) + i];
            float x = (float)i / GRID * 2.0f - 1.0f, y = (float)j / GRID * 2.0f - 1.0f;
            float h = 0.25f * expf(-4.0f * (x * x + y * y)) * cosf(9.0f * sqrtf(x * x + y * y));
            v[0] = 0.4f + 2.0f * h;
            v[1] = 0.5f + 0.5f * y;
            v[2] = 0.8f - 0.4f * x;
            v[3] = x;
            v[4] = y;
            v[5] = h;
        }
    }
    for (j = 0; j < GRID; ++j) {
        for (i = 0; i < GRID; ++i) {
            GLushort v = (GLushort)(j * (GRID + 1) + i);
            indices[k++] = v;
            indices[k++] = (GLushort)(v + 1);
            indices[k++] = (GLushort)(v + GRID + 2);
            indices[k++] = v;
            indices[k++] = (GLushort)(v + GRID + 2);
            indices[k++] = (GLushort)(v + GRID + 1);
        }
    }
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, wireframe ? GL_LINE : GL_FILL);
    glInterleavedArrays(GL_C3F_V3F, 0, mesh);
    glDrawElements(GL_TRIANGLES, GRID * GRID * 6, GL_UNSIGNED_SHORT, indices);
    glPopMatrix();
    glutSwapBuffers();
}

static void idle(void) {
    angle += 7.0f;
    if (angle > 360.0f) angle -= 360.0f;
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    if (key == 'w') {
        wireframe = !wireframe;
        glutPostRedisplay();
    }
}

static void reshape(int w, int h) {
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 0.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.2f);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("mesh viewer");
    buildMesh();
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
