/* Specular highlights on textured objects, as in the red book's discussion of
 * GL_SEPARATE_SPECULAR_COLOR: the same checkered teapot and sphere lit twice, on the left with
 * the single lit colour (the texture modulates the highlight away), on the right with the
 * specular term kept apart and added after texturing (white highlights over the texture).
 * Ported by changing only the include (was <GL/glut.h>). */
#include <mygl/glut.h>

#define CHECKER 32

static float angle = 10.0f;
static GLubyte checker[CHECKER][CHECKER][3];

static void makeChecker(void) {
    int i, j;
    for (i = 0; i < CHECKER; i++) {
        for (j = 0; j < CHECKER; j++) {
            int dark = ((i & 4) == 0) ^ ((j & 4) == 0);
            checker[i][j][0] = (GLubyte)(dark ? 40 : 230);
            checker[i][j][1] = (GLubyte)(dark ? 60 : 120);
            checker[i][j][2] = (GLubyte)(dark ? 160 : 40);
        }
    }
}

static void drawPair(float x, GLint colorControl) {
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, colorControl);
    glPushMatrix();
    glTranslatef(x, 0.6f, 0.0f);
    glRotatef(angle, 0.2f, 1.0f, 0.0f);
    glutSolidTeapot(0.7);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(x, -1.0f, 0.0f);
    glRotatef(angle, 1.0f, 0.0f, 0.0f);
    {
        GLUquadric* sphere = gluNewQuadric();
        gluQuadricTexture(sphere, GL_TRUE);
        gluSphere(sphere, 0.6, 24, 16);
        gluDeleteQuadric(sphere);
    }
    glPopMatrix();
}

static void display(void) {
    static const GLfloat lightPosition[] = {1.0f, 2.0f, 4.0f, 1.0f};
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
    drawPair(-1.1f, GL_SINGLE_COLOR);
    drawPair(1.1f, GL_SEPARATE_SPECULAR_COLOR);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
}

static void idle(void) {
    angle += 9.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat shininess[] = {40.0f};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(480, 320);
    glutCreateWindow("Separate specular colour");
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);

    makeChecker();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, CHECKER, CHECKER, 0, GL_RGB, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);

    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialfv(GL_FRONT, GL_SHININESS, shininess);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);

    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
