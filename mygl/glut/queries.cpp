// glutGet, glutDeviceGet, glutLayerGet, glutGetModifiers and glutSetOption.
#include <chrono>
#include <cstdio>

#include "runtime.h"

using glut::runtime;

int glutGet(GLenum query) {
    const glut::Runtime& r = runtime();
    const bool window = r.windowExists;
    switch (query) {
    case GLUT_ELAPSED_TIME:
        if (r.captureFrames > 0) return static_cast<int>(r.now);  // simulated: 16 ms a frame
        return static_cast<int>(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r.start).count());
    case GLUT_WINDOW_WIDTH: return window ? r.width : 0;
    case GLUT_WINDOW_HEIGHT: return window ? r.height : 0;
    case GLUT_WINDOW_X: return window ? r.x : 0;
    case GLUT_WINDOW_Y: return window ? r.y : 0;
    case GLUT_WINDOW_RED_SIZE:
    case GLUT_WINDOW_GREEN_SIZE:
    case GLUT_WINDOW_BLUE_SIZE:
    case GLUT_WINDOW_ALPHA_SIZE: return window ? 8 : 0;
    case GLUT_WINDOW_BUFFER_SIZE: return window ? 32 : 0;
    case GLUT_WINDOW_DEPTH_SIZE: return window ? 24 : 0;
    case GLUT_WINDOW_STENCIL_SIZE: return window ? 8 : 0;  // every window has an 8-bit stencil buffer
    case GLUT_WINDOW_DOUBLEBUFFER: return window && (r.displayMode & GLUT_DOUBLE) ? 1 : 0;
    case GLUT_WINDOW_RGBA: return window ? 1 : 0;
    case GLUT_WINDOW_NUM_SAMPLES:
    case GLUT_WINDOW_STEREO: return 0;
    case GLUT_WINDOW_PARENT:
    case GLUT_WINDOW_NUM_CHILDREN:
    case GLUT_WINDOW_COLORMAP_SIZE: return 0;
    case GLUT_WINDOW_CURSOR: return GLUT_CURSOR_INHERIT;
    case GLUT_SCREEN_WIDTH: return 1920;  // what the window system would say is not asked
    case GLUT_SCREEN_HEIGHT: return 1080;
    case GLUT_MENU_NUM_ITEMS: return r.menus.itemCount();
    case GLUT_DISPLAY_MODE_POSSIBLE: return (r.displayMode & (GLUT_INDEX | GLUT_STEREO)) == 0 ? 1 : 0;
    case GLUT_INIT_WINDOW_WIDTH: return r.width;
    case GLUT_INIT_WINDOW_HEIGHT: return r.height;
    case GLUT_INIT_WINDOW_X: return r.x;
    case GLUT_INIT_WINDOW_Y: return r.y;
    case GLUT_INIT_DISPLAY_MODE: return static_cast<int>(r.displayMode);
    case GLUT_ACTION_ON_WINDOW_CLOSE: return r.actionOnWindowClose;
    case GLUT_FULL_SCREEN: return r.fullScreen ? 1 : 0;
    case GLUT_INIT_STATE: return 1;
    case GLUT_VERSION: return 30400;  // the freeglut API level this follows (3.4.0)
    case GLUT_RENDERING_CONTEXT: return GLUT_CREATE_NEW_CONTEXT;
    case GLUT_DIRECT_RENDERING: return 1;
    default: std::fprintf(stderr, "mygl glut: glutGet(0x%04X) is not answered; 0\n", query); return 0;
    }
}

int glutDeviceGet(GLenum query) {
    switch (query) {
    case GLUT_HAS_KEYBOARD:
    case GLUT_HAS_MOUSE: return 1;
    case GLUT_NUM_MOUSE_BUTTONS: return 3;
    case GLUT_DEVICE_IGNORE_KEY_REPEAT: return runtime().ignoreKeyRepeat ? 1 : 0;
    case GLUT_DEVICE_KEY_REPEAT: return runtime().ignoreKeyRepeat ? GLUT_KEY_REPEAT_OFF : GLUT_KEY_REPEAT_ON;
    default: return 0;  // no spaceball, dials, tablet or joystick
    }
}

int glutLayerGet(GLenum query) {
    // There are no overlays: the normal plane is the layer in use and never damaged by one.
    switch (query) {
    case GLUT_LAYER_IN_USE: return GLUT_NORMAL;
    case GLUT_TRANSPARENT_INDEX: return -1;
    default: return 0;
    }
}

int glutGetModifiers() { return runtime().modifiers; }

int glutExtensionSupported(const char*) { return 0; }

void glutSetOption(GLenum option, int value) {
    switch (option) {
    case GLUT_ACTION_ON_WINDOW_CLOSE: runtime().actionOnWindowClose = value; break;
    case GLUT_INIT_WINDOW_WIDTH: glutInitWindowSize(value, runtime().height); break;
    case GLUT_INIT_WINDOW_HEIGHT: glutInitWindowSize(runtime().width, value); break;
    case GLUT_INIT_WINDOW_X: runtime().x = value; break;
    case GLUT_INIT_WINDOW_Y: runtime().y = value; break;
    case GLUT_INIT_DISPLAY_MODE: runtime().displayMode = static_cast<unsigned>(value); break;
    default: break;  // rendering context, multisampling, ...: nothing to choose here
    }
}
