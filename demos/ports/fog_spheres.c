/* A row of lit spheres fading into fog, in the style of the red book's fog.c: the fog mode
 * cycles EXP, EXP2, LINEAR with each frame (the 'f' key in the original), a grey-blue fog
 * colour that is also the clear colour, the spheres turning, the depth test on. Ported by
 * changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

static const GLint fogModes[] = {GL_EXP, GL_EXP2, GL_LINEAR};
static int fogIndex = 0;
static float angle = 0.0f;

static void sphereAt(float x, float z, const GLfloat* diffuse) {
    glPushMatrix();
    glTranslatef(x, -0.2f, z);
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
    glutSolidSphere(0.6, 20, 14);
    glPopMatrix();
}

static void display(void) {
    static const GLfloat colors[5][4] = {{0.9f, 0.3f, 0.2f, 1.0f},
                                         {0.9f, 0.7f, 0.2f, 1.0f},
                                         {0.3f, 0.8f, 0.3f, 1.0f},
                                         {0.2f, 0.5f, 0.9f, 1.0f},
                                         {0.7f, 0.3f, 0.8f, 1.0f}};
    int i;
    glFogi(GL_FOG_MODE, fogModes[fogIndex]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (i = 0; i < 5; ++i) sphereAt(-2.0f + 1.0f * (float)i, -3.0f - 2.5f * (float)i, colors[i]);
    /* A floor of flat-shaded quads, fogged too. */
    glDisable(GL_LIGHTING);
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    for (i = 0; i < 12; ++i) {
        glColor3f(i % 2 ? 0.8f : 0.4f, 0.8f, 0.5f);
        glVertex3f(-6.0f, -0.8f, 1.0f - 1.5f * (float)i);
        glVertex3f(6.0f, -0.8f, 1.0f - 1.5f * (float)i);
        glVertex3f(6.0f, -0.8f, -0.5f - 1.5f * (float)i);
        glVertex3f(-6.0f, -0.8f, -0.5f - 1.5f * (float)i);
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void idle(void) {
    angle += 11.0f;
    fogIndex = (fogIndex + 1) % 3;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    static const GLfloat fogColor[] = {0.5f, 0.55f, 0.6f, 1.0f};
    static const GLfloat lightPosition[] = {1.0f, 3.0f, 2.0f, 0.0f};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("Fog");
    glClearColor(0.5f, 0.55f, 0.6f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fogColor);
    glFogf(GL_FOG_DENSITY, 0.12f);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 16.0f);
    glHint(GL_FOG_HINT, GL_DONT_CARE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
