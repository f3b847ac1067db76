#pragma once
// A GLUT-style layer for course programs: replace `#include <GL/glut.h>` with
// `#include <mygl/glut.h>` and the program runs on MyGL (or OSMesa) unchanged. Calls to gl* go
// through the GL loader table; the backend comes from the environment:
//   MYGL_BACKEND=mygl (default) | osmesa | compare   (compare: MyGL, checked against OSMesa)
//   MYGL_CAPTURE=N:DIR   render N frames headless into DIR/frame-NNN*.png and exit
// Without MYGL_CAPTURE a GLFW window shows the frames (MYGL_SCREENSHOT=FILE.png saves what the
// window shows after its first frame, then exits).
#include <glad/gl.h>
#include <mygl/glu.h>

inline constexpr unsigned GLUT_RGB = 0, GLUT_RGBA = 0, GLUT_SINGLE = 0, GLUT_DOUBLE = 2, GLUT_DEPTH = 16;
inline constexpr int GLUT_KEY_F1 = 1, GLUT_KEY_F2 = 2, GLUT_KEY_F3 = 3, GLUT_KEY_F4 = 4, GLUT_KEY_F5 = 5,
                     GLUT_KEY_F6 = 6, GLUT_KEY_F7 = 7, GLUT_KEY_F8 = 8, GLUT_KEY_F9 = 9, GLUT_KEY_F10 = 10,
                     GLUT_KEY_F11 = 11, GLUT_KEY_F12 = 12, GLUT_KEY_LEFT = 100, GLUT_KEY_UP = 101,
                     GLUT_KEY_RIGHT = 102, GLUT_KEY_DOWN = 103;
inline constexpr int GLUT_LEFT_BUTTON = 0, GLUT_MIDDLE_BUTTON = 1, GLUT_RIGHT_BUTTON = 2, GLUT_DOWN = 0, GLUT_UP = 1;
inline constexpr GLenum GLUT_ELAPSED_TIME = 700, GLUT_WINDOW_WIDTH = 102, GLUT_WINDOW_HEIGHT = 103;

void glutInit(int* argc, char** argv);
void glutInitDisplayMode(unsigned mode);
void glutInitWindowSize(int width, int height);
void glutInitWindowPosition(int x, int y);
int glutCreateWindow(const char* title);
void glutDisplayFunc(void (*display)());
void glutReshapeFunc(void (*reshape)(int width, int height));
void glutKeyboardFunc(void (*keyboard)(unsigned char key, int x, int y));
void glutSpecialFunc(void (*special)(int key, int x, int y));
void glutMouseFunc(void (*mouse)(int button, int state, int x, int y));
void glutMotionFunc(void (*motion)(int x, int y));
void glutIdleFunc(void (*idle)());
void glutTimerFunc(unsigned milliseconds, void (*timer)(int value), int value);
void glutPostRedisplay();
void glutSwapBuffers();
int glutGet(GLenum what);
void glutMainLoop();

// The GLUT shapes, built from glBegin/glEnd with normals.
void glutSolidCube(GLdouble size);
void glutWireCube(GLdouble size);
void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);
void glutWireSphere(GLdouble radius, GLint slices, GLint stacks);
void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
void glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
void glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
