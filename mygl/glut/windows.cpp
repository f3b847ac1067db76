// GLUT's window calls. There is one window: its size is the backends' framebuffer size; what a
// headless run cannot show (position, full screen, icons, cursors) is accepted and ignored.
#include <cstdio>

#include "presenter.h"
#include "runtime.h"

using glut::runtime;

namespace {

// Window calls name the one window by id 1.
constexpr int kWindowId = 1;

bool hasWindow(const char* call) {
    if (runtime().windowExists) return true;
    std::fprintf(stderr, "mygl glut: %s without a window\n", call);
    return false;
}

}  // namespace

void glutInitWindowSize(int width, int height) {
    if (width > 0 && height > 0 && width <= mygl::Context::kMaxSize && height <= mygl::Context::kMaxSize) {
        runtime().width = width;
        runtime().height = height;
    }
}
void glutInitWindowPosition(int x, int y) {
    runtime().x = x;
    runtime().y = y;
}
void glutInitDisplayMode(unsigned mode) { runtime().displayMode = mode; }
void glutInitDisplayString(const char*) {}
// The context is GL 1.x compatibility whatever a program asks for.
void glutInitContextVersion(int, int) {}
void glutInitContextFlags(int) {}
void glutInitContextProfile(int) {}

int glutCreateWindow(const char* title) {
    glut::Runtime& r = runtime();
    if (r.windowExists) glut::fail("this GLUT runs one window; glutCreateWindow was called twice");
    r.title = title ? title : "MyGL";
    if (r.backend != glut::Backend::OSMesa) r.mygl = std::make_unique<mygl::Context>(r.width, r.height);
    if (r.backend != glut::Backend::MyGL) r.osmesa = std::make_unique<reference::OsmesaContext>(r.width, r.height);
    r.windowExists = true;
    glut::makeProgramContextCurrent(r);
    if (r.backend == glut::Backend::Compare) r.recorder.start();
    if (r.captureFrames == 0) glut::openWindow(r);
    return kWindowId;
}

void glutDestroyWindow(int window) {
    if (window != kWindowId || !hasWindow("glutDestroyWindow")) return;
    glut::windowClosed(runtime());
}

void glutSetWindow(int window) {
    if (window != kWindowId) std::fprintf(stderr, "mygl glut: glutSetWindow(%d): no such window\n", window);
}
int glutGetWindow() { return runtime().windowExists ? kWindowId : 0; }

void glutSetWindowTitle(const char* title) {
    glut::Runtime& r = runtime();
    if (!title || !hasWindow("glutSetWindowTitle")) return;
    r.title = title;
    if (r.window) r.window->setTitle(title);
}
void glutSetIconTitle(const char*) {}

void glutReshapeWindow(int width, int height) {
    glut::Runtime& r = runtime();
    if (!hasWindow("glutReshapeWindow")) return;
    r.pendingSize = {width, height};
    if (r.window) r.window->resize(width, height);
}

void glutPositionWindow(int x, int y) {
    runtime().x = x;
    runtime().y = y;
    runtime().fullScreen = false;
}
void glutFullScreen() { runtime().fullScreen = true; }
void glutLeaveFullScreen() { runtime().fullScreen = false; }
void glutFullScreenToggle() { runtime().fullScreen = !runtime().fullScreen; }
void glutShowWindow() {}
void glutHideWindow() {}
void glutIconifyWindow() {}
void glutPushWindow() {}
void glutPopWindow() {}
void glutWarpPointer(int, int) {}
void glutSetCursor(int) {}
void glutIgnoreKeyRepeat(int ignore) { runtime().ignoreKeyRepeat = ignore != 0; }
void glutSetKeyRepeat(int mode) { runtime().ignoreKeyRepeat = mode == GLUT_KEY_REPEAT_OFF; }
