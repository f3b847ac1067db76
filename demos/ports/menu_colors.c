/* Pop-up menus: a right-click menu picks the shape's colour (a submenu) and its shape, and
 * quits; the menu status callback stops the animation while a menu is open. Headless, the
 * menus are built and attached but never opened. Ported by changing only the include. */
#include <math.h>
#include <mygl/glut.h>

enum { SHAPE_SQUARE = 1, SHAPE_TRIANGLE, SHAPE_STAR, QUIT = 99 };

static float red = 1.0f, green = 0.3f, blue = 0.3f;
static int shape = SHAPE_STAR;
static int menuOpen = 0;
static float angle = 0.0f;

static void display(void) {
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    glColor3f(red, green, blue);
    if (shape == SHAPE_SQUARE) {
        glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
    } else if (shape == SHAPE_TRIANGLE) {
        glBegin(GL_TRIANGLES);
        glVertex2f(-0.6f, -0.5f);
        glVertex2f(0.6f, -0.5f);
        glVertex2f(0.0f, 0.6f);
        glEnd();
    } else {
        glBegin(GL_TRIANGLE_FAN);
        glVertex2f(0.0f, 0.0f);
        for (i = 0; i <= 10; i++) {
            float r = (i % 2) ? 0.3f : 0.7f;
            float a = 3.14159265f * 2.0f * (float)i / 10.0f;
            glVertex2f(r * sinf(a), r * cosf(a));
        }
        glEnd();
    }
    glutSwapBuffers();
}

static void colorMenu(int value) {
    switch (value) {
    case 1:
        red = 1.0f;
        green = 0.3f;
        blue = 0.3f;
        break;
    case 2:
        red = 0.3f;
        green = 1.0f;
        blue = 0.3f;
        break;
    case 3:
        red = 0.3f;
        green = 0.3f;
        blue = 1.0f;
        break;
    }
    glutPostRedisplay();
}

static void mainMenu(int value) {
    if (value == QUIT) exit(0);
    shape = value;
    glutPostRedisplay();
}

static void menuStatus(int status, int x, int y) {
    (void)x, (void)y;
    menuOpen = status == GLUT_MENU_IN_USE;
}

static void idle(void) {
    if (!menuOpen) {
        angle += 4.0f;
        glutPostRedisplay();
    }
}

int main(int argc, char** argv) {
    int colors;
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Menus");

    colors = glutCreateMenu(colorMenu);
    glutAddMenuEntry("Red", 1);
    glutAddMenuEntry("Green", 2);
    glutAddMenuEntry("Blue", 3);

    glutCreateMenu(mainMenu);
    glutAddSubMenu("Colour", colors);
    glutAddMenuEntry("Square", SHAPE_SQUARE);
    glutAddMenuEntry("Triangle", SHAPE_TRIANGLE);
    glutAddMenuEntry("Star", SHAPE_STAR);
    glutAddMenuEntry("Quit", QUIT);
    glutChangeToMenuEntry(4, "Star (default)", SHAPE_STAR);
    glutAttachMenu(GLUT_RIGHT_BUTTON);

    glutMenuStatusFunc(menuStatus);
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
