/* Conway's game of life on a 40 x 30 grid: a glider gun's worth of cells drawn as squares, one
 * generation per timer tick; a click toggles a cell, 'r' restarts. Ported by changing only the
 * include (was <GL/glut.h>). */
#include <string.h>
#include <mygl/glut.h>

#define COLUMNS 40
#define ROWS 30

static unsigned char grid[ROWS][COLUMNS], next[ROWS][COLUMNS];

static void seed(void) {
    static const int cells[][2] = {{1, 5},  {2, 5},  {1, 6},  {2, 6},  {11, 5}, {11, 6}, {11, 7}, {12, 4}, {12, 8},
                                   {13, 3}, {13, 9}, {14, 3}, {14, 9}, {15, 6}, {16, 4}, {16, 8}, {17, 5}, {17, 6},
                                   {17, 7}, {18, 6}, {21, 3}, {21, 4}, {21, 5}, {22, 3}, {22, 4}, {22, 5}, {23, 2},
                                   {23, 6}, {25, 1}, {25, 2}, {25, 6}, {25, 7}, {35, 3}, {35, 4}, {36, 3}, {36, 4}};
    size_t i;
    memset(grid, 0, sizeof grid);
    for (i = 0; i < sizeof cells / sizeof cells[0]; i++) grid[ROWS - 1 - cells[i][1]][cells[i][0]] = 1;
}

static void step(void) {
    int r, c, dr, dc;
    for (r = 0; r < ROWS; r++)
        for (c = 0; c < COLUMNS; c++) {
            int n = 0;
            for (dr = -1; dr <= 1; dr++)
                for (dc = -1; dc <= 1; dc++)
                    if ((dr || dc) && r + dr >= 0 && r + dr < ROWS && c + dc >= 0 && c + dc < COLUMNS)
                        n += grid[r + dr][c + dc];
            next[r][c] = (unsigned char)(n == 3 || (n == 2 && grid[r][c]));
        }
    memcpy(grid, next, sizeof grid);
}

static void display(void) {
    int r, c;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.2f, 0.9f, 0.3f);
    for (r = 0; r < ROWS; r++)
        for (c = 0; c < COLUMNS; c++)
            if (grid[r][c]) glRecti(c * 10 + 1, r * 10 + 1, c * 10 + 9, r * 10 + 9);
    glutSwapBuffers();
}

static void timer(int value) {
    step();
    glutPostRedisplay();
    glutTimerFunc(16, timer, value);
}

static void mouse(int button, int state, int x, int y) {
    if (button == GLUT_LEFT_BUTTON && state == GLUT_DOWN) {
        int c = x / 10, r = (glutGet(GLUT_WINDOW_HEIGHT) - 1 - y) / 10;
        if (r >= 0 && r < ROWS && c >= 0 && c < COLUMNS) grid[r][c] = (unsigned char)!grid[r][c];
        glutPostRedisplay();
    }
}

static void keyboard(unsigned char key, int x, int y) {
    (void)x, (void)y;
    if (key == 'r') seed();
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(COLUMNS * 10, ROWS * 10);
    glutCreateWindow("Life");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, COLUMNS * 10, 0.0, ROWS * 10);
    glMatrixMode(GL_MODELVIEW);
    seed();
    glutDisplayFunc(display);
    glutMouseFunc(mouse);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(16, timer, 0);
    glutMainLoop();
    return 0;
}
