/* freeglut's own loop: the program calls glutMainLoopEvent itself and stops when it wants to,
 * with glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS) so that
 * closing the window ends the loop instead of the program. Ported by changing only the
 * include (was <GL/freeglut.h>). */
#include <stdio.h>
#include <mygl/glut.h>

static int running = 1, frames = 0;

static void display(void) {
    float shade = (float)(frames % 10) / 10.0f;
    glClearColor(0.1f, 0.1f + 0.5f * shade, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0f, 1.0f - shade, 0.2f);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-0.7f, -0.5f);
    glVertex2f(-0.7f + 0.1f * (float)frames, 0.5f);
    glVertex2f(0.0f, -0.5f);
    glVertex2f(0.5f, 0.4f);
    glEnd();
    glutSwapBuffers();
    frames++;
}

static void onClose(void) { running = 0; }

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(240, 200);
    glutCreateWindow("glutMainLoopEvent");
    glutDisplayFunc(display);
    glutCloseFunc(onClose);
    while (running && frames < 1000) {
        glutPostRedisplay();
        glutMainLoopEvent();
    }
    printf("left the loop after %d frames\n", frames);
    return 0;
}
