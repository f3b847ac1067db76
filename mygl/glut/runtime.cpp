// The GLUT runtime: the backends, frames (captured headless or shown in the window) and the
// main loop.
#include "runtime.h"

#include <reference/compare.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "presenter.h"

namespace glut {
namespace {

// Simulated time of a captured frame: animation advances as at 60 frames a second.
constexpr double kCaptureFrameMilliseconds = 16.0;

void readEnvironment(Runtime& r) {
    if (const char* backend = std::getenv("MYGL_BACKEND")) {
        const std::string b = backend;
        if (b == "osmesa")
            r.backend = Backend::OSMesa;
        else if (b == "compare")
            r.backend = Backend::Compare;
        else if (b != "mygl")
            fail("MYGL_BACKEND must be mygl, osmesa or compare, not '" + b + "'");
    }
    if (const char* capture = std::getenv("MYGL_CAPTURE")) {
        const std::string c = capture;
        const auto colon = c.find(':');
        r.captureFrames = std::atoi(c.substr(0, colon).c_str());
        if (colon == std::string::npos || r.captureFrames <= 0) fail("MYGL_CAPTURE must be N:DIR, e.g. 3:out");
        r.captureDir = c.substr(colon + 1);
        std::filesystem::create_directories(r.captureDir);
    }
}

// The frame the program drew, read back (and in compare mode the same calls replayed on OSMesa).
struct FrameImages {
    reference::Image program, reference;  // reference only in compare mode
};

FrameImages readFrame(Runtime& r) {
    FrameImages images;
    images.program = {r.width, r.height, r.backend == Backend::OSMesa ? r.osmesa->readPixels() : r.mygl->readPixels()};
    if (r.backend == Backend::Compare) {
        r.recorder.stop();
        r.osmesa->makeCurrent();
        r.recorder.replay();  // everything MyGL received since the last frame
        r.recorder.clear();
        images.reference = {r.width, r.height, r.osmesa->readPixels()};
        r.mygl->makeCurrent();
        r.recorder.start();
    }
    return images;
}

void capture(Runtime& r, const FrameImages& images) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%03d", r.framesCaptured);
    const std::string base = r.captureDir + "/" + name;
    reference::writePng(base + (r.backend == Backend::OSMesa ? "-osmesa.png" : "-mygl.png"), images.program);
    if (r.backend == Backend::Compare) {
        reference::writePng(base + "-osmesa.png", images.reference);
        reference::writePng(base + "-diff.png", reference::diffImage(images.program, images.reference));
        std::printf("%s %s\n", name,
                    reference::toString(reference::compareImages(images.program, images.reference)).c_str());
    }
    ++r.framesCaptured;
    r.now = kCaptureFrameMilliseconds * r.framesCaptured;
    if (r.framesCaptured == r.captureFrames) {
        std::fflush(stdout);
        std::exit(0);
    }
}

// Before the first frame, as GLUT does when the window is mapped: the size, then visibility.
void windowShown(Runtime& r) {
    r.shown = true;
    if (!r.pendingSize) r.pendingSize = {r.width, r.height};
    applyPendingSize(r);
    makeProgramContextCurrent(r);
    if (r.callbacks.visibility) r.callbacks.visibility(GLUT_VISIBLE);
    if (r.callbacks.windowStatus) r.callbacks.windowStatus(GLUT_FULLY_RETAINED);
}

// Headless: every pass draws a frame (so a program without animation still gives N frames).
void capturePass(Runtime& r) {
    runDueTimers(r);
    if (r.leaveMainLoop) return;
    makeProgramContextCurrent(r);
    if (r.callbacks.idle) r.callbacks.idle();
    if (r.leaveMainLoop) return;
    applyPendingSize(r);
    callDisplay(r);
}

}  // namespace

Runtime& runtime() {
    static Runtime r;
    return r;
}

void runDueTimers(Runtime& r) {
    std::vector<Timer> due;
    for (auto it = r.timers.begin(); it != r.timers.end();) {
        if (it->due <= r.now) {
            due.push_back(*it);
            it = r.timers.erase(it);
        } else {
            ++it;
        }
    }
    for (const Timer& t : due) t.callback(t.value);
}

void callDisplay(Runtime& r) {
    makeProgramContextCurrent(r);
    r.redisplay = false;
    r.swappedInDisplay = false;
    r.callbacks.display();
    if (!r.swappedInDisplay) frameDone(r);  // single-buffered programs end with glFlush
    r.swappedInDisplay = false;
}

void fail(const std::string& message) {
    std::fprintf(stderr, "mygl glut: %s\n", message.c_str());
    std::exit(2);
}

// MyGL is only made current when it is not already: that reloads the table, which would drop
// the recorder's wrappers in compare mode.
void makeProgramContextCurrent(Runtime& r) {
    if (r.backend == Backend::OSMesa)
        r.osmesa->makeCurrent();
    else if (mygl::Context::current() != r.mygl.get())
        r.mygl->makeCurrent();
}

void frameDone(Runtime& r) {
    if (!r.windowExists) return;
    const FrameImages images = readFrame(r);
    if (r.captureFrames > 0) return capture(r, images);
    if (r.window) presentFrame(r, images.program);
}

void applyPendingSize(Runtime& r) {
    if (!r.pendingSize || !r.windowExists) return;
    const auto [width, height] = *r.pendingSize;
    r.pendingSize.reset();
    if (width < 1 || height < 1 || width > mygl::Context::kMaxSize || height > mygl::Context::kMaxSize) return;
    r.width = width;
    r.height = height;
    if (r.mygl && (r.mygl->width() != width || r.mygl->height() != height)) r.mygl->resize(width, height);
    if (r.osmesa && (r.osmesa->width() != width || r.osmesa->height() != height)) r.osmesa->resize(width, height);
    makeProgramContextCurrent(r);
    if (r.callbacks.reshape)
        r.callbacks.reshape(width, height);
    else
        glViewport(0, 0, width, height);
    r.redisplay = true;
}

void windowClosed(Runtime& r) {
    if (r.callbacks.close) {
        makeProgramContextCurrent(r);
        r.callbacks.close();
    }
    r.windowExists = false;
    if (r.actionOnWindowClose == GLUT_ACTION_EXIT) {
        std::fflush(stdout);
        std::exit(0);
    }
    r.leaveMainLoop = true;
}

}  // namespace glut

using glut::runtime;

void glutInit(int*, char**) {
    glut::Runtime& r = runtime();
    glut::readEnvironment(r);
    r.start = std::chrono::steady_clock::now();
}

void glutMainLoop() {
    glut::Runtime& r = runtime();
    if (!r.callbacks.display) glut::fail("glutMainLoop called without glutDisplayFunc");
    if (!r.windowExists) glut::fail("glutMainLoop called without glutCreateWindow");
    r.leaveMainLoop = false;
    if (!r.shown) glut::windowShown(r);
    if (r.captureFrames > 0) {
        while (!r.leaveMainLoop && r.windowExists) glut::capturePass(r);
    } else {
        glut::runWindow(r);
    }
}

void glutMainLoopEvent() {
    glut::Runtime& r = runtime();
    if (!r.windowExists || !r.callbacks.display) return;
    if (!r.shown) glut::windowShown(r);
    if (r.captureFrames > 0)
        glut::capturePass(r);
    else
        glut::windowPass(r);
}

void glutLeaveMainLoop() { runtime().leaveMainLoop = true; }

void glutExit() {
    std::fflush(stdout);
    std::exit(0);
}

void glutPostRedisplay() { runtime().redisplay = true; }
void glutPostWindowRedisplay(int) { runtime().redisplay = true; }

// In capture mode every swap is a frame, so a program that loops inside its display function
// is captured too; in the window the frame is shown.
void glutSwapBuffers() {
    glut::Runtime& r = runtime();
    if (!r.windowExists) return;
    glut::frameDone(r);
    r.swappedInDisplay = true;
    glut::makeProgramContextCurrent(r);
}
