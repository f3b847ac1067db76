// GLUT's menu calls, on the menus kept in the runtime.
#include "runtime.h"

using glut::runtime;

int glutCreateMenu(void (*callback)(int)) { return runtime().menus.create(callback); }
void glutDestroyMenu(int menu) { runtime().menus.destroy(menu); }
int glutGetMenu() { return runtime().menus.current(); }
void glutSetMenu(int menu) { runtime().menus.setCurrent(menu); }
void glutAddMenuEntry(const char* label, int value) { runtime().menus.add({label ? label : "", value, false}); }
void glutAddSubMenu(const char* label, int subMenu) { runtime().menus.add({label ? label : "", subMenu, true}); }
void glutChangeToMenuEntry(int item, const char* label, int value) {
    runtime().menus.change(item, {label ? label : "", value, false});
}
void glutChangeToSubMenu(int item, const char* label, int subMenu) {
    runtime().menus.change(item, {label ? label : "", subMenu, true});
}
void glutRemoveMenuItem(int item) { runtime().menus.remove(item); }
void glutAttachMenu(int button) { runtime().menus.attach(button, runtime().menus.current()); }
void glutDetachMenu(int button) { runtime().menus.attach(button, 0); }
