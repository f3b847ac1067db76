// The GLUT-style runtime: callbacks, the main loop, headless capture and the window.
#include <mygl/context.h>
#include <mygl/glut.h>
#include <reference/call_recorder.h>
#include <reference/compare.h>
#include <reference/osmesa_context.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "presenter.h"

namespace {

enum class Backend { MyGL, OSMesa, Compare };

struct Timer {
    double due;  // milliseconds since glutInit
    void (*callback)(int);
    int value;
};

struct Runtime {
    Backend backend = Backend::MyGL;
    int captureFrames = 0;  // > 0: headless, that many frames
    std::string captureDir;
    int width = 300, height = 300;
    std::string title = "MyGL";
    void (*display)() = nullptr;
    void (*reshape)(int, int) = nullptr;
    void (*keyboard)(unsigned char, int, int) = nullptr;
    void (*special)(int, int, int) = nullptr;
    void (*mouse)(int, int, int, int) = nullptr;
    void (*motion)(int, int) = nullptr;
    void (*idle)() = nullptr;
    std::vector<Timer> timers;
    bool redisplay = true;
    double now = 0;  // milliseconds; simulated (16 ms a frame) when capturing
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::unique_ptr<mygl::Context> mygl;
    std::unique_ptr<reference::OsmesaContext> osmesa;
    reference::CallRecorder recorder;  // compare mode: MyGL's calls, replayed on OSMesa
    std::unique_ptr<Presenter> window;
};

Runtime& runtime() {
    static Runtime r;
    return r;
}

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "mygl glut: %s\n", message.c_str());
    std::exit(2);
}

void readEnvironment(Runtime& r) {
    if (const char* backend = std::getenv("MYGL_BACKEND")) {
        const std::string b = backend;
        if (b == "osmesa") r.backend = Backend::OSMesa;
        else if (b == "compare") r.backend = Backend::Compare;
        else if (b != "mygl") fail("MYGL_BACKEND must be mygl, osmesa or compare, not '" + b + "'");
    }
    if (const char* capture = std::getenv("MYGL_CAPTURE")) {
        const std::string c = capture;
        const auto colon = c.find(':');
        r.captureFrames = std::atoi(c.substr(0, colon).c_str());
        if (colon == std::string::npos || r.captureFrames <= 0) fail("MYGL_CAPTURE must be N:DIR, e.g. 3:out");
        r.captureDir = c.substr(colon + 1);
    }
}

// Points the GL table at the backend the program draws on (MyGL unless OSMesa alone). MyGL is
// only made current when it is not already: that reloads the table, which would drop the
// recorder's wrappers in compare mode.
void makeProgramContextCurrent(Runtime& r) {
    if (r.backend == Backend::OSMesa) r.osmesa->makeCurrent();
    else if (mygl::Context::current() != r.mygl.get()) r.mygl->makeCurrent();
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

struct FrameImages {
    reference::Image program, reference;  // reference only in compare mode
};

// Calls the display function and reads the frame back (both backends in compare mode).
FrameImages renderFrame(Runtime& r) {
    makeProgramContextCurrent(r);
    r.display();
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

void capture(Runtime& r) {
    std::filesystem::create_directories(r.captureDir);
    for (int frame = 0; frame < r.captureFrames; ++frame) {
        r.now = 16.0 * frame;
        runDueTimers(r);
        if (r.idle) r.idle();
        const FrameImages images = renderFrame(r);
        char name[32];
        std::snprintf(name, sizeof name, "frame-%03d", frame);
        const std::string base = r.captureDir + "/" + name;
        reference::writePng(base + (r.backend == Backend::OSMesa ? "-osmesa.png" : "-mygl.png"), images.program);
        if (r.backend == Backend::Compare) {
            reference::writePng(base + "-osmesa.png", images.reference);
            reference::writePng(base + "-diff.png", reference::diffImage(images.program, images.reference));
            std::printf("%s %s\n", name, reference::toString(reference::compareImages(images.program, images.reference)).c_str());
        }
    }
    std::fflush(stdout);
    std::exit(0);
}

void interactive(Runtime& r) {
    r.window = std::make_unique<Presenter>(r.width, r.height, r.title + (r.backend == Backend::OSMesa ? " [OSMesa]" : " [MyGL]"));
    Presenter::Callbacks callbacks;
    callbacks.key = [&r](unsigned char key, int x, int y) {
        if (r.keyboard) r.keyboard(key, x, y);
    };
    callbacks.special = [&r](int key, int x, int y) {
        if (r.special) r.special(key, x, y);
    };
    callbacks.mouse = [&r](int button, int state, int x, int y) {
        if (r.mouse) r.mouse(button, state, x, y);
    };
    callbacks.motion = [&r](int x, int y) {
        if (r.motion) r.motion(x, y);
    };
    r.window->setCallbacks(callbacks);
    while (!r.window->shouldClose()) {
        r.window->pollEvents();
        r.now = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r.start).count();
        runDueTimers(r);
        if (r.idle) r.idle();
        if (!r.redisplay) {
            r.window->waitBriefly();
            continue;
        }
        r.redisplay = false;
        r.window->present(renderFrame(r).program);
        if (const char* path = std::getenv("MYGL_SCREENSHOT")) {  // what the window shows, then exit
            reference::writePng(path, r.window->screenshot());
            std::exit(0);
        }
    }
    std::exit(0);
}

}  // namespace

void glutInit(int*, char**) { readEnvironment(runtime()); }
void glutInitDisplayMode(unsigned) {}
void glutInitWindowSize(int width, int height) {
    if (width > 0 && height > 0 && width <= mygl::Context::kMaxSize && height <= mygl::Context::kMaxSize) {
        runtime().width = width;
        runtime().height = height;
    }
}
void glutInitWindowPosition(int, int) {}

int glutCreateWindow(const char* title) {
    Runtime& r = runtime();
    r.title = title ? title : "MyGL";
    if (r.backend != Backend::OSMesa) r.mygl = std::make_unique<mygl::Context>(r.width, r.height);
    if (r.backend != Backend::MyGL) r.osmesa = std::make_unique<reference::OsmesaContext>(r.width, r.height);
    makeProgramContextCurrent(r);
    if (r.backend == Backend::Compare) r.recorder.start();
    return 1;
}

void glutDisplayFunc(void (*display)()) { runtime().display = display; }
void glutReshapeFunc(void (*reshape)(int, int)) { runtime().reshape = reshape; }
void glutKeyboardFunc(void (*keyboard)(unsigned char, int, int)) { runtime().keyboard = keyboard; }
void glutSpecialFunc(void (*special)(int, int, int)) { runtime().special = special; }
void glutMouseFunc(void (*mouse)(int, int, int, int)) { runtime().mouse = mouse; }
void glutMotionFunc(void (*motion)(int, int)) { runtime().motion = motion; }
void glutIdleFunc(void (*idle)()) { runtime().idle = idle; }
void glutTimerFunc(unsigned ms, void (*timer)(int), int value) {
    if (timer) runtime().timers.push_back({runtime().now + ms, timer, value});
}
void glutPostRedisplay() { runtime().redisplay = true; }
void glutSwapBuffers() {}  // the runtime presents the frame when the display function returns

int glutGet(GLenum what) {
    const Runtime& r = runtime();
    if (what == GLUT_ELAPSED_TIME) return static_cast<int>(r.now);
    if (what == GLUT_WINDOW_WIDTH) return r.width;
    if (what == GLUT_WINDOW_HEIGHT) return r.height;
    return 0;
}

void glutMainLoop() {
    Runtime& r = runtime();
    if (!r.display) fail("glutMainLoop called without glutDisplayFunc");
    if (!r.mygl && !r.osmesa) fail("glutMainLoop called without glutCreateWindow");
    if (r.reshape) {
        makeProgramContextCurrent(r);
        r.reshape(r.width, r.height);
    }
    if (r.captureFrames > 0) capture(r);
    interactive(r);
}
