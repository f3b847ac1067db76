/* Bezier curves and surfaces in the style of the red book's bezcurve.c and bezmesh.c: a lit
 * 4x4 surface through glMap2f, glMapGrid2f and glEvalMesh2 with GL_AUTO_NORMAL, its control
 * points as dots, and a curve through glMap1f and glEvalCoord1f. Ported by changing only the
 * include (was <GL/glut.h>). */
#include <mygl/glut.h>

static GLfloat ctrlpoints[4][4][3] = {
    {{-1.5f, -1.5f, 4.0f}, {-0.5f, -1.5f, 2.0f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 2.0f}},
    {{-1.5f, -0.5f, 1.0f}, {-0.5f, -0.5f, 3.0f}, {0.5f, -0.5f, 0.0f}, {1.5f, -0.5f, -1.0f}},
    {{-1.5f, 0.5f, 4.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}, {1.5f, 0.5f, 4.0f}},
    {{-1.5f, 1.5f, -2.0f}, {-0.5f, 1.5f, -2.0f}, {0.5f, 1.5f, 0.0f}, {1.5f, 1.5f, -1.0f}}};
static GLfloat curve[4][3] = {{-4.0f, -3.0f, 0.0f}, {-2.0f, 3.0f, 0.0f}, {2.0f, -3.0f, 0.0f}, {4.0f, 3.0f, 0.0f}};
static float angle = 85.0f;

static void display(void) {
    int i, j;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glPushMatrix();
    glTranslatef(0.0f, 0.8f, 0.0f);
    glRotatef(angle, 1.0f, 1.0f, 1.0f);
    glEnable(GL_LIGHTING);
    glEvalMesh2(GL_FILL, 0, 20, 0, 20);
    glDisable(GL_LIGHTING);
    glPointSize(4.0f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) glVertex3fv(&ctrlpoints[i][j][0]);
    glEnd();
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.0f, -3.2f, 0.0f);
    glScalef(0.6f, 0.25f, 1.0f);
    glColor3f(0.4f, 0.9f, 1.0f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i <= 30; i++) glEvalCoord1f((GLfloat)i / 30.0f);
    glEnd();
    glPopMatrix();
    glutSwapBuffers();
}

static void init(void) {
    static const GLfloat ambient[] = {0.2f, 0.2f, 0.2f, 1.0f}, position[] = {0.0f, 0.0f, 2.0f, 1.0f};
    static const GLfloat diffuse[] = {0.6f, 0.6f, 0.6f, 1.0f}, specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &ctrlpoints[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(20, 0.0f, 1.0f, 20, 0.0f, 1.0f);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 50.0f);
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-5.0, 5.0, -5.0 * (GLfloat)h / (GLfloat)w, 5.0 * (GLfloat)h / (GLfloat)w, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void idle(void) {
    angle += 11.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 320);
    glutCreateWindow("Bezier surface");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
