/* Scene antialiasing with the accumulation buffer, in the style of the red book's accanti.c:
 * the scene is drawn eight times through a frustum jittered by a fraction of a pixel, each
 * image added to the accumulation buffer with weight 1/8 (GL_ACCUM), and the average returned
 * to the colour buffer (GL_RETURN). The objects turn a little with each frame. Ported by
 * changing only the include (was <GL/glut.h>). */
#include <math.h>
#include <mygl/glut.h>

#define ACSIZE 8

/* The red book's jitter table for eight samples (jitter.h), in pixels. */
static const GLfloat jitter8[ACSIZE][2] = {{-0.334818f, 0.435331f},  {0.286438f, -0.393495f}, {0.459462f, 0.141540f},
                                           {-0.414498f, -0.192829f}, {-0.183790f, 0.082102f}, {-0.079263f, -0.317383f},
                                           {0.102254f, 0.299133f},   {0.164216f, -0.054399f}};

static float angle = 0.0f;

/* A perspective frustum moved by (pixdx, pixdy) pixels: accFrustum/accPerspective of the book. */
static void accPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar, GLdouble pixdx,
                           GLdouble pixdy) {
    GLint viewport[4];
    GLdouble fov2 = ((fovy * 3.14159265358979323846) / 180.0) / 2.0;
    GLdouble top = zNear / (cos(fov2) / sin(fov2));
    GLdouble bottom = -top;
    GLdouble right = top * aspect;
    GLdouble left = -right;
    GLdouble xwsize = right - left, ywsize = top - bottom;
    GLdouble dx, dy;
    glGetIntegerv(GL_VIEWPORT, viewport);
    dx = -(pixdx * xwsize / (GLdouble)viewport[2]);
    dy = -(pixdy * ywsize / (GLdouble)viewport[3]);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(left + dx, right + dx, bottom + dy, top + dy, zNear, zFar);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void material(GLfloat r, GLfloat g, GLfloat b) {
    GLfloat diffuse[4];
    diffuse[0] = r;
    diffuse[1] = g;
    diffuse[2] = b;
    diffuse[3] = 1.0f;
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
}

static void displayObjects(void) {
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(30.0f + angle, 1.0f, 0.0f, 0.0f);

    glPushMatrix();
    glTranslatef(-0.80f, 0.35f, 0.0f);
    glRotatef(100.0f, 1.0f, 0.0f, 0.0f);
    material(0.7f, 0.7f, 0.0f);
    glutSolidTorus(0.275, 0.85, 16, 16);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(-0.75f, -0.50f, 0.0f);
    glRotatef(45.0f, 0.0f, 0.0f, 1.0f);
    glRotatef(45.0f, 1.0f, 0.0f, 0.0f);
    material(0.1f, 0.5f, 0.8f);
    glutSolidCube(1.5);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.75f, 0.60f, 0.0f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    material(0.8f, 0.3f, 0.3f);
    glutSolidSphere(1.0, 16, 16);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.70f, -0.90f, 0.25f);
    material(0.5f, 0.8f, 0.5f);
    glutSolidOctahedron();
    glPopMatrix();

    glPopMatrix();
}

static void display(void) {
    GLint viewport[4];
    int jitter;
    glGetIntegerv(GL_VIEWPORT, viewport);
    glClear(GL_ACCUM_BUFFER_BIT);
    for (jitter = 0; jitter < ACSIZE; jitter++) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        accPerspective(50.0, (GLdouble)viewport[2] / (GLdouble)viewport[3], 1.0, 15.0, jitter8[jitter][0],
                       jitter8[jitter][1]);
        displayObjects();
        glAccum(GL_ACCUM, 1.0f / ACSIZE);
    }
    glAccum(GL_RETURN, 1.0f);
    glutSwapBuffers();
}

static void reshape(int w, int h) { glViewport(0, 0, w, h); }

static void idle(void) {
    angle += 7.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    static const GLfloat ambient[] = {0.0f, 0.0f, 0.0f, 1.0f};
    static const GLfloat diffuse[] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat position[] = {0.0f, 3.0f, 3.0f, 0.0f};
    static const GLfloat lmodelAmbient[] = {0.2f, 0.2f, 0.2f, 1.0f};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_ACCUM | GLUT_DEPTH);
    glutInitWindowSize(250, 250);
    glutCreateWindow("Scene antialiasing");
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, lmodelAmbient);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glutReshapeFunc(reshape);
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
