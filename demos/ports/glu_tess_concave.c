/* Tessellation: concave polygons (an arrow, an L and a comb) that glBegin(GL_POLYGON) would
 * fill wrongly, drawn through the GLU tessellator: left as GL_POLYGON, right tessellated.
 * 'w' shows the triangles GLU produced as wireframe. */
#include <stdlib.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

static GLUtesselator* tess;
static int wire = 0;

static GLdouble arrow[7][3] = {{0, 1, 0},    {-1, 0, 0},  {-0.4, 0, 0}, {-0.4, -1, 0},
                               {0.4, -1, 0}, {0.4, 0, 0}, {1, 0, 0}};
static GLdouble ell[6][3] = {{-0.8, 0.9, 0}, {-0.8, -0.9, 0}, {0.8, -0.9, 0},
                             {0.8, -0.4, 0}, {-0.3, -0.4, 0}, {-0.3, 0.9, 0}};
static GLdouble comb[10][3] = {{-0.9, -0.8, 0}, {0.9, -0.8, 0}, {0.9, 0.9, 0},  {0.5, 0.9, 0},   {0.5, -0.2, 0},
                               {0.2, -0.2, 0},  {0.2, 0.9, 0},  {-0.2, 0.9, 0}, {-0.2, -0.2, 0}, {-0.9, -0.2, 0}};

static void beginCallback(GLenum mode) { glBegin(mode); }
static void endCallback(void) { glEnd(); }
static void vertexCallback(GLvoid* vertex) { glVertex3dv((const GLdouble*)vertex); }
static void errorCallback(GLenum code) { (void)gluErrorString(code); }

static void shape(GLdouble (*points)[3], int count, int tessellated) {
    int i;
    if (!tessellated) {
        glBegin(GL_POLYGON);
        for (i = 0; i < count; ++i) glVertex3dv(points[i]);
        glEnd();
        return;
    }
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (i = 0; i < count; ++i) gluTessVertex(tess, points[i], points[i]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

static void display(void) {
    int column;
    glClear(GL_COLOR_BUFFER_BIT);
    for (column = 0; column < 2; ++column) {
        glPolygonMode(GL_FRONT_AND_BACK, column == 1 && wire ? GL_LINE : GL_FILL);
        glLoadIdentity();
        glTranslatef(column ? 1.6f : -1.6f, 0.0f, 0.0f);
        glPushMatrix();
        glTranslatef(0.0f, 2.1f, 0.0f);
        glColor3f(0.9f, 0.4f, 0.2f);
        shape(arrow, 7, column);
        glPopMatrix();
        glColor3f(0.3f, 0.8f, 0.4f);
        shape(ell, 6, column);
        glPushMatrix();
        glTranslatef(0.0f, -2.1f, 0.0f);
        glColor3f(0.3f, 0.5f, 1.0f);
        shape(comb, 10, column);
        glPopMatrix();
    }
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-3.0, 3.0, -3.2, 3.2);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x;
    (void)y;
    if (key == 'w') wire = !wire;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(360, 380);
    glutCreateWindow("concave polygons: GL_POLYGON vs gluTess");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)endCallback);
    gluTessCallback(tess, GLU_TESS_ERROR, (_GLUfuncptr)errorCallback);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    gluDeleteTess(tess);
    return 0;
}
