// The GLUT window: GLFW input turned into the program's callbacks, the frames shown, and an
// attached menu opened by its mouse button.
#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "menu_overlay.h"
#include "presenter.h"
#include "runtime.h"

namespace glut {
namespace {

struct WindowState {
    MenuOverlay menu;
    reference::Image lastFrame;  // shown again when a menu opens or closes over it
};

WindowState& windowState() {
    static WindowState state;
    return state;
}

// Calls a program callback with its context current and glutGetModifiers answering.
template <class Call>
void toProgram(Runtime& r, Call call) {
    makeProgramContextCurrent(r);
    r.modifiers = r.window->modifiers();
    call();
    r.modifiers = 0;
}

void showMenuChange(Runtime& r) {
    if (!windowState().lastFrame.rgba.empty()) presentFrame(r, windowState().lastFrame);
}

void menuInUse(Runtime& r, bool inUse, int x, int y) {
    toProgram(r, [&] {
        if (r.callbacks.menuStatus) r.callbacks.menuStatus(inUse ? GLUT_MENU_IN_USE : GLUT_MENU_NOT_IN_USE, x, y);
        if (r.callbacks.menuState) r.callbacks.menuState(inUse ? GLUT_MENU_IN_USE : GLUT_MENU_NOT_IN_USE);
    });
}

void onMouse(Runtime& r, int button, int state, int x, int y) {
    MenuOverlay& overlay = windowState().menu;
    if (overlay.isOpen()) {
        if (state != GLUT_UP) return;
        const std::optional<MenuChoice> choice = overlay.release(r.menus, x, y);
        if (!overlay.isOpen()) menuInUse(r, false, x, y);
        if (choice) {
            const Menu* menu = r.menus.find(choice->menu);
            toProgram(r, [&] {
                r.menus.setCurrent(choice->menu);  // GLUT's current menu during its callback
                if (menu && menu->callback) menu->callback(choice->value);
            });
        }
        showMenuChange(r);
        return;
    }
    if (state == GLUT_DOWN && r.menus.attached(button) != 0) {
        overlay.open(r.menus.attached(button), x, y);
        menuInUse(r, true, x, y);
        showMenuChange(r);
        return;
    }
    if (r.callbacks.mouse) toProgram(r, [&] { r.callbacks.mouse(button, state, x, y); });
}

void setCallbacks(Runtime& r) {
    Presenter::Callbacks c;
    c.key = [&r](unsigned char key, int x, int y, bool down) {
        auto* f = down ? r.callbacks.keyboard : r.callbacks.keyboardUp;
        if (f) toProgram(r, [&] { f(key, x, y); });
    };
    c.special = [&r](int key, int x, int y, bool down) {
        auto* f = down ? r.callbacks.special : r.callbacks.specialUp;
        if (f) toProgram(r, [&] { f(key, x, y); });
    };
    c.mouse = [&r](int button, int state, int x, int y) { onMouse(r, button, state, x, y); };
    c.wheel = [&r](int direction, int x, int y) {
        // Without a wheel callback freeglut reports the wheel as buttons 3 (up) and 4 (down).
        if (r.callbacks.mouseWheel) return toProgram(r, [&] { r.callbacks.mouseWheel(0, direction, x, y); });
        const int button = direction > 0 ? 3 : 4;
        if (r.callbacks.mouse)
            toProgram(r, [&] {
                r.callbacks.mouse(button, GLUT_DOWN, x, y);
                r.callbacks.mouse(button, GLUT_UP, x, y);
            });
    };
    c.motion = [&r](int x, int y, bool buttonDown) {
        if (windowState().menu.isOpen()) {
            windowState().menu.hover(x, y);
            return showMenuChange(r);
        }
        auto* f = buttonDown ? r.callbacks.motion : r.callbacks.passiveMotion;
        if (f) toProgram(r, [&] { f(x, y); });
    };
    c.entry = [&r](bool entered) {
        if (r.callbacks.entry) toProgram(r, [&] { r.callbacks.entry(entered ? GLUT_ENTERED : GLUT_LEFT); });
    };
    c.resized = [&r](int width, int height) {
        if (width != r.width || height != r.height) r.pendingSize = {width, height};
    };
    r.window->setCallbacks(c);
}

}  // namespace

void openWindow(Runtime& r) {
    try {
        r.window = std::make_unique<Presenter>(r.width, r.height, r.title);
    } catch (const std::runtime_error& e) {
        fail(std::string(e.what()) + "; MYGL_CAPTURE=N:DIR runs the program headless");
    }
    setCallbacks(r);
}

void presentFrame(Runtime& r, const reference::Image& frame) {
    WindowState& w = windowState();
    if (&frame != &w.lastFrame) w.lastFrame = frame;
    reference::Image shown = frame;
    w.menu.draw(shown, r.menus);
    r.window->present(shown);
    if (const char* path = std::getenv("MYGL_SCREENSHOT")) {  // what the window shows, then exit
        reference::writePng(path, r.window->screenshot());
        std::exit(0);
    }
}

void windowPass(Runtime& r) {
    r.window->setKeyRepeat(!r.ignoreKeyRepeat);
    r.window->pollEvents();
    if (r.window->shouldClose()) return windowClosed(r);
    r.now = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r.start).count();
    makeProgramContextCurrent(r);  // the window's GL was bound to show the last frame
    runDueTimers(r);
    if (r.callbacks.idle) r.callbacks.idle();
    applyPendingSize(r);
    if (r.redisplay)
        callDisplay(r);
    else if (!r.callbacks.idle)
        r.window->waitBriefly();
}

void runWindow(Runtime& r) {
    while (!r.leaveMainLoop && r.windowExists) windowPass(r);
}

}  // namespace glut
