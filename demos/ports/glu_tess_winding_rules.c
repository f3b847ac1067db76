/* Tessellation: the five winding rules side by side on the same three overlapping contours (two
 * nested squares wound the same way and a third one crossing them), in the style of the Red
 * Book's winding example. Each panel fills what its rule keeps; the contours are outlined. */
#include <stdlib.h>

#include <mygl/glut.h>
#include <mygl/glu.h>

static GLUtesselator* tess;
static GLdouble contours[3][4][3] = {
    {{-0.9, -0.9, 0}, {0.9, -0.9, 0}, {0.9, 0.9, 0}, {-0.9, 0.9, 0}},
    {{-0.6, -0.6, 0}, {0.6, -0.6, 0}, {0.6, 0.6, 0}, {-0.6, 0.6, 0}},
    {{-0.2, -1.0, 0}, {-0.2, 1.0, 0}, {1.1, 1.0, 0}, {1.1, -1.0, 0}},
};
static GLdouble combined[64][3];
static int combinedCount;

static void beginCallback(GLenum mode) { glBegin(mode); }
static void endCallback(void) { glEnd(); }
static void vertexCallback(GLvoid* vertex) { glVertex3dv((const GLdouble*)vertex); }
static void combineCallback(GLdouble coords[3], void* data[4], GLfloat weights[4], void** out) {
    GLdouble* v = combined[combinedCount++ % 64];
    (void)data;
    (void)weights;
    v[0] = coords[0];
    v[1] = coords[1];
    v[2] = coords[2];
    *out = v;
}

static void display(void) {
    static const GLenum rules[5] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
                                    GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO};
    int panel, c, i;
    glClear(GL_COLOR_BUFFER_BIT);
    for (panel = 0; panel < 5; ++panel) {
        glLoadIdentity();
        glTranslatef(-4.8f + 2.4f * panel, 0.0f, 0.0f);
        gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[panel]);
        glColor3f(0.25f + 0.15f * panel, 0.7f - 0.1f * panel, 0.9f - 0.12f * panel);
        combinedCount = 0;
        gluTessBeginPolygon(tess, NULL);
        for (c = 0; c < 3; ++c) {
            gluTessBeginContour(tess);
            for (i = 0; i < 4; ++i) gluTessVertex(tess, contours[c][i], contours[c][i]);
            gluTessEndContour(tess);
        }
        gluTessEndPolygon(tess);
        glColor3f(1.0f, 1.0f, 1.0f);
        for (c = 0; c < 3; ++c) {
            glBegin(GL_LINE_LOOP);
            for (i = 0; i < 4; ++i) glVertex3dv(contours[c][i]);
            glEnd();
        }
    }
    glutSwapBuffers();
}

static void reshape(int width, int height) {
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-6.0, 6.0, -1.3, 1.3);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(600, 140);
    glutCreateWindow("winding rules: odd, nonzero, positive, negative, abs >= 2");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)endCallback);
    gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combineCallback);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
