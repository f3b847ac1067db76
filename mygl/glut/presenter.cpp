#include "presenter.h"

#include <mygl/glut.h>  // GL types and enums through glad, before GLFW (which must not include GL)
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>

// The few GL 1.1 functions the window needs, typed here and loaded from GLFW's context.
struct Presenter::Functions {
    void(GLAD_API_PTR* viewport)(GLint, GLint, GLsizei, GLsizei);
    void(GLAD_API_PTR* rasterPos2f)(GLfloat, GLfloat);
    void(GLAD_API_PTR* pixelZoom)(GLfloat, GLfloat);
    void(GLAD_API_PTR* drawPixels)(GLsizei, GLsizei, GLenum, GLenum, const void*);
    void(GLAD_API_PTR* readPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    void(GLAD_API_PTR* pixelStorei)(GLenum, GLint);
    void(GLAD_API_PTR* finish)();
};

namespace {

template <class Function>
void load(Function& f, const char* name) {
    f = reinterpret_cast<Function>(glfwGetProcAddress(name));
    if (!f) throw std::runtime_error(std::string("the window's GL lacks ") + name);
}

int glutSpecialKey(int key) {
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return GLUT_KEY_F1 + (key - GLFW_KEY_F1);
    switch (key) {
    case GLFW_KEY_LEFT: return GLUT_KEY_LEFT;
    case GLFW_KEY_RIGHT: return GLUT_KEY_RIGHT;
    case GLFW_KEY_UP: return GLUT_KEY_UP;
    case GLFW_KEY_DOWN: return GLUT_KEY_DOWN;
    case GLFW_KEY_PAGE_UP: return GLUT_KEY_PAGE_UP;
    case GLFW_KEY_PAGE_DOWN: return GLUT_KEY_PAGE_DOWN;
    case GLFW_KEY_HOME: return GLUT_KEY_HOME;
    case GLFW_KEY_END: return GLUT_KEY_END;
    case GLFW_KEY_INSERT: return GLUT_KEY_INSERT;
    case GLFW_KEY_NUM_LOCK: return GLUT_KEY_NUM_LOCK;
    case GLFW_KEY_LEFT_SHIFT: return GLUT_KEY_SHIFT_L;
    case GLFW_KEY_RIGHT_SHIFT: return GLUT_KEY_SHIFT_R;
    case GLFW_KEY_LEFT_CONTROL: return GLUT_KEY_CTRL_L;
    case GLFW_KEY_RIGHT_CONTROL: return GLUT_KEY_CTRL_R;
    case GLFW_KEY_LEFT_ALT: return GLUT_KEY_ALT_L;
    case GLFW_KEY_RIGHT_ALT: return GLUT_KEY_ALT_R;
    case GLFW_KEY_LEFT_SUPER: return GLUT_KEY_SUPER_L;
    case GLFW_KEY_RIGHT_SUPER: return GLUT_KEY_SUPER_R;
    default: return 0;
    }
}

// Keys GLUT reports through the keyboard callback although they type no text.
int controlCharacter(int key) {
    switch (key) {
    case GLFW_KEY_ESCAPE: return 27;
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER: return 13;
    case GLFW_KEY_TAB: return 9;
    case GLFW_KEY_BACKSPACE: return 8;
    case GLFW_KEY_DELETE: return 127;
    default: return 0;
    }
}

int glutModifiers(int mods) {
    return (mods & GLFW_MOD_SHIFT ? GLUT_ACTIVE_SHIFT : 0) | (mods & GLFW_MOD_CONTROL ? GLUT_ACTIVE_CTRL : 0) |
           (mods & GLFW_MOD_ALT ? GLUT_ACTIVE_ALT : 0);
}

Presenter& owner(GLFWwindow* window) { return *static_cast<Presenter*>(glfwGetWindowUserPointer(window)); }

}  // namespace

Presenter::Presenter(int width, int height, const std::string& title) {
    if (!glfwInit()) throw std::runtime_error("GLFW cannot start (no display?)");
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("GLFW cannot open a window (no display?)");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    gl_ = new Functions;
    load(gl_->viewport, "glViewport");
    load(gl_->rasterPos2f, "glRasterPos2f");
    load(gl_->pixelZoom, "glPixelZoom");
    load(gl_->drawPixels, "glDrawPixels");
    load(gl_->readPixels, "glReadPixels");
    load(gl_->pixelStorei, "glPixelStorei");
    load(gl_->finish, "glFinish");
    glfwSetWindowUserPointer(window_, this);
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned codepoint) { owner(w).onChar(codepoint); });
    glfwSetKeyCallback(window_,
                       [](GLFWwindow* w, int key, int, int action, int mods) { owner(w).onKey(key, action, mods); });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int mods) {
        Presenter& p = owner(w);
        p.modifiers_ = glutModifiers(mods);
        if (button > 2) return;
        // GLFW numbers left, right, middle; GLUT left, middle, right.
        const int glutButton = button == GLFW_MOUSE_BUTTON_RIGHT    ? GLUT_RIGHT_BUTTON
                               : button == GLFW_MOUSE_BUTTON_MIDDLE ? GLUT_MIDDLE_BUTTON
                                                                    : GLUT_LEFT_BUTTON;
        if (action == GLFW_PRESS)
            p.buttonsDown_ |= 1 << glutButton;
        else
            p.buttonsDown_ &= ~(1 << glutButton);
        int x, y;
        p.cursor(x, y);
        if (p.callbacks_.mouse) p.callbacks_.mouse(glutButton, action == GLFW_PRESS ? GLUT_DOWN : GLUT_UP, x, y);
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
        Presenter& p = owner(w);
        int x, y;
        p.cursor(x, y);
        if (dy != 0 && p.callbacks_.wheel) p.callbacks_.wheel(dy > 0 ? 1 : -1, x, y);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        Presenter& p = owner(w);
        if (p.callbacks_.motion) p.callbacks_.motion(static_cast<int>(x), static_cast<int>(y), p.buttonsDown_ != 0);
    });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int entered) {
        if (owner(w).callbacks_.entry) owner(w).callbacks_.entry(entered == GLFW_TRUE);
    });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int newWidth, int newHeight) {
        if (newWidth > 0 && newHeight > 0 && owner(w).callbacks_.resized)
            owner(w).callbacks_.resized(newWidth, newHeight);
    });
}

Presenter::~Presenter() {
    delete gl_;
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void Presenter::cursor(int& x, int& y) const {
    double cx, cy;
    glfwGetCursorPos(window_, &cx, &cy);
    x = static_cast<int>(cx);
    y = static_cast<int>(cy);
}

void Presenter::onKey(int key, int action, int mods) {
    modifiers_ = glutModifiers(mods);
    if (action == GLFW_REPEAT && !keyRepeat_) return;
    const bool down = action != GLFW_RELEASE;
    int x, y;
    cursor(x, y);
    if (const int special = glutSpecialKey(key)) {
        if (callbacks_.special) callbacks_.special(special, x, y, down);
        return;
    }
    if (down) lastKeyPressed_ = key;
    int character = controlCharacter(key);
    if (!character && (mods & GLFW_MOD_CONTROL) && key >= GLFW_KEY_A && key <= GLFW_KEY_Z)
        character = key - GLFW_KEY_A + 1;  // GLUT's control characters: Ctrl+A is 1
    if (character) {
        if (down) keyChars_[key] = static_cast<unsigned char>(character);
        if (callbacks_.key) callbacks_.key(static_cast<unsigned char>(character), x, y, down);
    } else if (!down) {
        // Text keys are reported down through onChar; up with the character they typed.
        const auto typed = keyChars_.find(key);
        if (typed != keyChars_.end() && callbacks_.key) callbacks_.key(typed->second, x, y, false);
    }
    if (!down) keyChars_.erase(key);
}

void Presenter::onChar(unsigned codepoint) {
    if (codepoint >= 256) return;  // GLUT's keyboard callback takes one Latin-1 byte
    keyChars_[lastKeyPressed_] = static_cast<unsigned char>(codepoint);
    int x, y;
    cursor(x, y);
    if (callbacks_.key) callbacks_.key(static_cast<unsigned char>(codepoint), x, y, true);
}

void Presenter::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
void Presenter::resize(int width, int height) {
    if (width > 0 && height > 0) glfwSetWindowSize(window_, width, height);
}
bool Presenter::shouldClose() const { return glfwWindowShouldClose(window_); }
void Presenter::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Presenter::pollEvents() { glfwPollEvents(); }
void Presenter::waitBriefly() { glfwWaitEventsTimeout(0.01); }

// OSMesa and the window's Mesa share the thread's current context (libglapi): after an
// OSMesaMakeCurrent, GLFW still believes its context is current and would skip binding it.
void Presenter::bindContext() {
    glfwMakeContextCurrent(nullptr);
    glfwMakeContextCurrent(window_);
}

void Presenter::present(const reference::Image& frame) {
    bindContext();
    int width, height;
    glfwGetFramebufferSize(window_, &width, &height);
    gl_->viewport(0, 0, width, height);
    gl_->pixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl_->rasterPos2f(-1.0f, -1.0f);  // the frame's bottom-left corner; rows go up, as ours do
    gl_->pixelZoom(static_cast<float>(width) / static_cast<float>(frame.width),
                   static_cast<float>(height) / static_cast<float>(frame.height));
    gl_->drawPixels(frame.width, frame.height, GL_RGBA, GL_UNSIGNED_BYTE, frame.rgba.data());
    glfwSwapBuffers(window_);
}

reference::Image Presenter::screenshot() {
    bindContext();
    int width, height;
    glfwGetFramebufferSize(window_, &width, &height);
    reference::Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    gl_->finish();
    gl_->pixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_->readPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    return image;
}
