/* The classic gears, built once into display lists at start-up and drawn each frame with
 * glCallList under their own rotation (glxgears' layout, flat-shaded colours). The idle
 * callback turns them; the arrow keys turn the view. Ported by changing only the include. */
#include <mygl/glut.h>
#include <math.h>

static GLuint gear1, gear2, gear3;
static GLfloat viewX = 20.0f, viewY = 30.0f, angle = 0.0f;

/* One gear: front and back faces as quad strips, the outward faces of the teeth and the inner
 * cylinder. */
static void gear(GLfloat inner, GLfloat outer, GLfloat width, GLint teeth, GLfloat toothDepth) {
    const GLfloat r0 = inner, r1 = outer - toothDepth / 2.0f, r2 = outer + toothDepth / 2.0f;
    const GLfloat da = 2.0f * (GLfloat)M_PI / (GLfloat)teeth / 4.0f;
    GLint i;
    GLfloat z;
    for (z = width * 0.5f; z >= -width * 0.5f; z -= width) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= teeth; i++) {
            GLfloat a = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
            glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
            glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
        }
        glEnd();
        glBegin(GL_QUADS);
        for (i = 0; i < teeth; i++) {
            GLfloat a = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
            glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
            glVertex3f(r2 * cosf(a + da), r2 * sinf(a + da), z);
            glVertex3f(r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), z);
            glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), z);
        }
        glEnd();
    }
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < teeth; i++) {
        GLfloat a = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
        glVertex3f(r1 * cosf(a), r1 * sinf(a), width * 0.5f);
        glVertex3f(r1 * cosf(a), r1 * sinf(a), -width * 0.5f);
        glVertex3f(r2 * cosf(a + da), r2 * sinf(a + da), width * 0.5f);
        glVertex3f(r2 * cosf(a + da), r2 * sinf(a + da), -width * 0.5f);
        glVertex3f(r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), width * 0.5f);
        glVertex3f(r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), -width * 0.5f);
        glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), width * 0.5f);
        glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), -width * 0.5f);
    }
    glVertex3f(r1, 0.0f, width * 0.5f);
    glVertex3f(r1, 0.0f, -width * 0.5f);
    glEnd();
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        GLfloat a = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
        glVertex3f(r0 * cosf(a), r0 * sinf(a), -width * 0.5f);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), width * 0.5f);
    }
    glEnd();
}

static GLuint compileGear(GLfloat r, GLfloat g, GLfloat b, GLfloat inner, GLfloat outer, GLfloat width, GLint teeth) {
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColor3f(r, g, b);
    gear(inner, outer, width, teeth, 0.7f);
    glEndList();
    return list;
}

static void drawGear(GLuint list, GLfloat x, GLfloat y, GLfloat rotation) {
    glPushMatrix();
    glTranslatef(x, y, 0.0f);
    glRotatef(rotation, 0.0f, 0.0f, 1.0f);
    glCallList(list);
    glPopMatrix();
}

static void display(void) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(viewX, 1.0f, 0.0f, 0.0f);
    glRotatef(viewY, 0.0f, 1.0f, 0.0f);
    drawGear(gear1, -3.0f, -2.0f, angle);
    drawGear(gear2, 3.1f, -2.0f, -2.0f * angle - 9.0f);
    drawGear(gear3, -3.1f, 4.2f, -2.0f * angle - 25.0f);
    glPopMatrix();
    glutSwapBuffers();
}

static void idle(void) {
    angle += 2.0f;
    glutPostRedisplay();
}

static void special(int key, int x, int y) {
    (void)x, (void)y;
    if (key == GLUT_KEY_UP) viewX += 5.0f;
    if (key == GLUT_KEY_DOWN) viewX -= 5.0f;
    if (key == GLUT_KEY_LEFT) viewY += 5.0f;
    if (key == GLUT_KEY_RIGHT) viewY -= 5.0f;
    glutPostRedisplay();
}

static void reshape(int w, int h) {
    GLfloat aspect = (GLfloat)h / (GLfloat)w;
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -aspect, aspect, 5.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -40.0f);
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(300, 300);
    glutCreateWindow("gears from display lists");
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_FLAT);
    gear1 = compileGear(0.8f, 0.1f, 0.0f, 1.0f, 4.0f, 1.0f, 20);
    gear2 = compileGear(0.0f, 0.8f, 0.2f, 0.5f, 2.0f, 2.0f, 10);
    gear3 = compileGear(0.2f, 0.2f, 1.0f, 1.3f, 2.0f, 0.5f, 10);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutSpecialFunc(special);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
