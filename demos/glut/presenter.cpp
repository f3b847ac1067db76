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
    default: return 0;
    }
}

Presenter& owner(GLFWwindow* window) { return *static_cast<Presenter*>(glfwGetWindowUserPointer(window)); }

}  // namespace

Presenter::Presenter(int width, int height, const std::string& title) {
    if (!glfwInit()) throw std::runtime_error("GLFW cannot start (no display?)");
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
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
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned codepoint) {
        double x, y;
        glfwGetCursorPos(w, &x, &y);
        if (codepoint < 128 && owner(w).callbacks_.key)
            owner(w).callbacks_.key(static_cast<unsigned char>(codepoint), static_cast<int>(x), static_cast<int>(y));
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        const int special = glutSpecialKey(key);
        double x, y;
        glfwGetCursorPos(w, &x, &y);
        if (action != GLFW_RELEASE && special && owner(w).callbacks_.special)
            owner(w).callbacks_.special(special, static_cast<int>(x), static_cast<int>(y));
        if (action == GLFW_PRESS && key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
        double x, y;
        glfwGetCursorPos(w, &x, &y);
        owner(w).buttonDown_ = action == GLFW_PRESS;
        if (owner(w).callbacks_.mouse)
            owner(w).callbacks_.mouse(button, action == GLFW_PRESS ? GLUT_DOWN : GLUT_UP, static_cast<int>(x), static_cast<int>(y));
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        if (owner(w).buttonDown_ && owner(w).callbacks_.motion) owner(w).callbacks_.motion(static_cast<int>(x), static_cast<int>(y));
    });
}

Presenter::~Presenter() {
    delete gl_;
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void Presenter::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
bool Presenter::shouldClose() const { return glfwWindowShouldClose(window_); }
void Presenter::pollEvents() { glfwPollEvents(); }
void Presenter::waitBriefly() { glfwWaitEventsTimeout(0.01); }

void Presenter::present(const reference::Image& frame) {
    glfwMakeContextCurrent(window_);
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
    glfwMakeContextCurrent(window_);
    int width, height;
    glfwGetFramebufferSize(window_, &width, &height);
    reference::Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    gl_->finish();
    gl_->pixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_->readPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    return image;
}
