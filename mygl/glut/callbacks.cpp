// Registering the program's callbacks (nullptr unregisters), and GLUT's timers.
#include "runtime.h"

using glut::runtime;

void glutDisplayFunc(void (*f)()) { runtime().callbacks.display = f; }
void glutReshapeFunc(void (*f)(int, int)) { runtime().callbacks.reshape = f; }
void glutKeyboardFunc(void (*f)(unsigned char, int, int)) { runtime().callbacks.keyboard = f; }
void glutKeyboardUpFunc(void (*f)(unsigned char, int, int)) { runtime().callbacks.keyboardUp = f; }
void glutSpecialFunc(void (*f)(int, int, int)) { runtime().callbacks.special = f; }
void glutSpecialUpFunc(void (*f)(int, int, int)) { runtime().callbacks.specialUp = f; }
void glutMouseFunc(void (*f)(int, int, int, int)) { runtime().callbacks.mouse = f; }
void glutMouseWheelFunc(void (*f)(int, int, int, int)) { runtime().callbacks.mouseWheel = f; }
void glutMotionFunc(void (*f)(int, int)) { runtime().callbacks.motion = f; }
void glutPassiveMotionFunc(void (*f)(int, int)) { runtime().callbacks.passiveMotion = f; }
void glutEntryFunc(void (*f)(int)) { runtime().callbacks.entry = f; }
void glutVisibilityFunc(void (*f)(int)) { runtime().callbacks.visibility = f; }
void glutWindowStatusFunc(void (*f)(int)) { runtime().callbacks.windowStatus = f; }
void glutIdleFunc(void (*f)()) { runtime().callbacks.idle = f; }
void glutMenuStateFunc(void (*f)(int)) { runtime().callbacks.menuState = f; }
void glutMenuStatusFunc(void (*f)(int, int, int)) { runtime().callbacks.menuStatus = f; }
void glutCloseFunc(void (*f)()) { runtime().callbacks.close = f; }
void glutWMCloseFunc(void (*f)()) { runtime().callbacks.close = f; }

void glutTimerFunc(unsigned milliseconds, void (*f)(int), int value) {
    if (f) runtime().timers.push_back({runtime().now + milliseconds, f, value});
}
