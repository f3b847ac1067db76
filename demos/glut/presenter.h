#pragma once
// A GLFW window that shows RGBA8 frames. Its own GL context is reached only through
// glfwGetProcAddress, into a few function pointers of its own: the program's GL table stays
// on MyGL or OSMesa, and no system GL symbol is ever linked.
#include <reference/image.h>

#include <functional>
#include <string>

struct GLFWwindow;

class Presenter {
public:
    struct Callbacks {
        std::function<void(unsigned char key, int x, int y)> key;
        std::function<void(int key, int x, int y)> special;  // GLUT_KEY_* codes
        std::function<void(int button, int state, int x, int y)> mouse;
        std::function<void(int x, int y)> motion;
    };

    // Throws std::runtime_error if no window can be opened (no display).
    Presenter(int width, int height, const std::string& title);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    void setCallbacks(Callbacks callbacks) { callbacks_ = std::move(callbacks); }
    void setTitle(const std::string& title);
    bool shouldClose() const;
    void pollEvents();
    void waitBriefly();
    void present(const reference::Image& frame);
    // The window's current contents, read back through its own context.
    reference::Image screenshot();

private:
    struct Functions;
    GLFWwindow* window_ = nullptr;
    Functions* gl_ = nullptr;
    Callbacks callbacks_;
    bool buttonDown_ = false;
};
