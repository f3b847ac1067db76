/* The Mandelbrot set drawn point by point with a colour per pixel, zooming in a little every
 * frame; the usual first "plot a function" exercise. Ported by changing only the include. */
#include <mygl/glut.h>

#define SIZE 200

static double centreX = -0.745, centreY = 0.11, scale = 3.0;

static void display(void) {
    int px, py, i;
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);
    for (py = 0; py < SIZE; py++)
        for (px = 0; px < SIZE; px++) {
            double cx = centreX + scale * ((px + 0.5) / SIZE - 0.5);
            double cy = centreY + scale * ((py + 0.5) / SIZE - 0.5);
            double zx = 0.0, zy = 0.0;
            for (i = 0; i < 64 && zx * zx + zy * zy < 4.0; i++) {
                double t = zx * zx - zy * zy + cx;
                zy = 2.0 * zx * zy + cy;
                zx = t;
            }
            if (i == 64)
                glColor3f(0.0f, 0.0f, 0.0f);
            else
                glColor3f((float)i / 64.0f, (float)(i % 8) / 8.0f, 1.0f - (float)i / 64.0f);
            glVertex2i(px, py);
        }
    glEnd();
    glutSwapBuffers();
}

static void idle(void) {
    scale *= 0.85;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(SIZE, SIZE);
    glutCreateWindow("Mandelbrot");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, SIZE, 0.0, SIZE);
    glMatrixMode(GL_MODELVIEW);
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
