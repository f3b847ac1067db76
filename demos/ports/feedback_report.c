/* Feedback mode, in the style of the red book's feedback.c: a small scene (a lit-less strip of
 * triangles, a line strip and points, a pass-through marker between them) is drawn in
 * GL_FEEDBACK mode into a GL_3D_COLOR buffer; the program parses the tokens, prints a short
 * report, and then draws the scene normally with a white square marked at every feedback
 * vertex (window coordinates, from the buffer) and the polygons' outlines in their feedback
 * colours. The scene turns with each frame. Ported by changing only the include (was
 * <GL/glut.h>). */
#include <stdio.h>
#include <mygl/glut.h>

#define BUFFER_SIZE 1024

static GLfloat feedbackBuffer[BUFFER_SIZE];
static float angle = 0.0f;
static int width = 320, height = 240;

static void drawScene(void) {
    int i;
    glPushMatrix();
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 6; i++) {
        glColor3f(0.2f + 0.15f * (float)i, 0.8f - 0.1f * (float)i, 0.4f);
        glVertex3f(-1.5f + 0.6f * (float)i, (i % 2) ? -0.2f : -0.9f, 0.0f);
    }
    glEnd();
    glPassThrough(1.0f);
    glColor3f(1.0f, 0.6f, 0.1f);
    glBegin(GL_LINE_STRIP);
    glVertex2f(-1.4f, 0.3f);
    glVertex2f(-0.3f, 0.9f);
    glVertex2f(0.6f, 0.4f);
    glVertex2f(2.5f, 1.2f); /* leaves the view: the line is clipped */
    glEnd();
    glPassThrough(2.0f);
    glColor3f(0.3f, 0.7f, 1.0f);
    glBegin(GL_POINTS);
    glVertex2f(-0.8f, -0.1f);
    glVertex2f(0.9f, 0.0f);
    glVertex2f(5.0f, 5.0f); /* outside: no token */
    glEnd();
    glPopMatrix();
}

static void setView(void) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.0, 2.0, -1.5, 1.5, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A small square at a window position, in window coordinates. */
static void mark(GLfloat x, GLfloat y) { glRectf(x - 2.0f, y - 2.0f, x + 2.0f, y + 2.0f); }

/* Walks the GL_3D_COLOR tokens: marks every vertex, outlines polygons and lines. */
static void drawReport(GLint count, int print) {
    GLint i = 0, polygons = 0, lines = 0, points = 0, passes = 0;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)width, 0.0, (double)height, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    while (i < count) {
        GLfloat token = feedbackBuffer[i++];
        GLint n = 0, k;
        if (token == GL_PASS_THROUGH_TOKEN) {
            i++;
            passes++;
            continue;
        }
        if (token == GL_POLYGON_TOKEN) {
            n = (GLint)feedbackBuffer[i++];
            polygons++;
        } else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN) {
            n = 2;
            lines++;
        } else if (token == GL_POINT_TOKEN) {
            n = 1;
            points++;
        } else {
            break;
        }
        /* each vertex: x y z r g b a */
        if (n > 1) {
            glBegin(GL_LINE_LOOP);
            for (k = 0; k < n; k++) {
                const GLfloat* v = &feedbackBuffer[i + 7 * k];
                glColor4f(v[3], v[4], v[5], v[6]);
                glVertex2f(v[0], v[1]);
            }
            glEnd();
        }
        glColor3f(1.0f, 1.0f, 1.0f);
        for (k = 0; k < n; k++) mark(feedbackBuffer[i + 7 * k], feedbackBuffer[i + 7 * k + 1]);
        i += 7 * n;
    }
    if (print)
        printf("feedback: %d values, %d polygons, %d lines, %d points, %d pass-throughs\n", (int)count, (int)polygons,
               (int)lines, (int)points, (int)passes);
}

static void display(void) {
    static int frame = 0;
    GLint count;
    setView();
    glFeedbackBuffer(BUFFER_SIZE, GL_3D_COLOR, feedbackBuffer);
    glRenderMode(GL_FEEDBACK);
    drawScene();
    count = glRenderMode(GL_RENDER);

    glClear(GL_COLOR_BUFFER_BIT);
    setView();
    drawScene();
    drawReport(count, frame++ == 0);
    glutSwapBuffers();
}

static void reshape(int w, int h) {
    width = w;
    height = h;
    glViewport(0, 0, w, h);
}

static void idle(void) {
    angle += 9.0f;
    glutPostRedisplay();
}

int main(int argc, char** argv) {
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Feedback report");
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glPointSize(5.0f);
    glutReshapeFunc(reshape);
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
