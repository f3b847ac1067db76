#pragma once
// The GLUT layer's state: the one window's backends, the callbacks, timers, menus, and how
// frames leave (a GLFW window, or headless capture). Internal to mygl_glut.
#include <mygl/context.h>
#include <mygl/glut.h>
#include <reference/call_recorder.h>
#include <reference/image.h>
#include <reference/osmesa_context.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "menus.h"

class Presenter;

namespace glut {

enum class Backend { MyGL, OSMesa, Compare };

struct Timer {
    double due;  // milliseconds since glutInit
    void (*callback)(int);
    int value;
};

struct Callbacks {
    void (*display)() = nullptr;
    void (*reshape)(int, int) = nullptr;
    void (*keyboard)(unsigned char, int, int) = nullptr;
    void (*keyboardUp)(unsigned char, int, int) = nullptr;
    void (*special)(int, int, int) = nullptr;
    void (*specialUp)(int, int, int) = nullptr;
    void (*mouse)(int, int, int, int) = nullptr;
    void (*mouseWheel)(int, int, int, int) = nullptr;
    void (*motion)(int, int) = nullptr;
    void (*passiveMotion)(int, int) = nullptr;
    void (*entry)(int) = nullptr;
    void (*visibility)(int) = nullptr;
    void (*windowStatus)(int) = nullptr;
    void (*idle)() = nullptr;
    void (*menuState)(int) = nullptr;
    void (*menuStatus)(int, int, int) = nullptr;
    void (*close)() = nullptr;
};

struct Runtime {
    Backend backend = Backend::MyGL;
    int captureFrames = 0;  // > 0: headless, that many frames
    std::string captureDir;
    int framesCaptured = 0;

    // glutInit* values, then the window's.
    int width = 300, height = 300, x = -1, y = -1;
    unsigned displayMode = GLUT_RGBA | GLUT_SINGLE | GLUT_DEPTH;
    std::string title = "MyGL";
    bool windowExists = false, fullScreen = false;
    bool shown = false;                              // the first reshape and visibility callbacks have run
    std::optional<std::pair<int, int>> pendingSize;  // glutReshapeWindow or a resized window

    Callbacks callbacks;
    std::vector<Timer> timers;
    Menus menus;
    bool redisplay = true;
    bool swappedInDisplay = false;  // a frame already left during this display call
    bool leaveMainLoop = false;
    bool ignoreKeyRepeat = false;
    int modifiers = 0;  // GLUT_ACTIVE_* during an input callback
    int actionOnWindowClose = GLUT_ACTION_EXIT;

    double now = 0;  // milliseconds; simulated (16 ms a frame) when capturing
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::unique_ptr<mygl::Context> mygl;
    std::unique_ptr<reference::OsmesaContext> osmesa;
    reference::CallRecorder recorder;  // compare mode: MyGL's calls, replayed on OSMesa
    std::unique_ptr<Presenter> window;
};

Runtime& runtime();

// Prints "mygl glut: message" and exits with status 2.
[[noreturn]] void fail(const std::string& message);

// Points the GL table at the backend the program draws on.
void makeProgramContextCurrent(Runtime& r);

// The frame the program just drew leaves: into the window, or captured (the program exits
// after the last captured frame).
void frameDone(Runtime& r);

// Calls the timer callbacks that are due (each once; they may add timers for later).
void runDueTimers(Runtime& r);
// Calls the display callback; a frame leaves when it swaps, or when it returns without swapping.
void callDisplay(Runtime& r);
// Shows a frame in the window, with an open menu drawn over it (interactive.cpp).
void presentFrame(Runtime& r, const reference::Image& frame);
// Opens the GLFW window, or fails with a message saying how to run headless (interactive.cpp).
void openWindow(Runtime& r);

// Applies a pending size to the backends and tells the program (reshape callback, or the
// default viewport).
void applyPendingSize(Runtime& r);

// Runs the window loop until the window closes or glutLeaveMainLoop (interactive.cpp).
void runWindow(Runtime& r);
// One pass of the window's events, timers, idle and redisplay (glutMainLoopEvent).
void windowPass(Runtime& r);

// Ends the main loop as GLUT_ACTION_ON_WINDOW_CLOSE says: the close callback, then exit or
// return from glutMainLoop.
void windowClosed(Runtime& r);

}  // namespace glut
