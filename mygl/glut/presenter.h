#pragma once
// A GLFW window that shows RGBA8 frames. Its own GL context is reached only through
// glfwGetProcAddress, into a few function pointers of its own: the program's GL table stays
// on MyGL or OSMesa, and no system GL symbol is ever linked.
#include <reference/image.h>

#include <functional>
#include <map>
#include <string>

struct GLFWwindow;

class Presenter {
public:
    // Input in GLUT's terms: window coordinates with y down, GLUT_KEY_* codes, GLUT buttons.
    struct Callbacks {
        std::function<void(unsigned char key, int x, int y, bool down)> key;
        std::function<void(int key, int x, int y, bool down)> special;
        std::function<void(int button, int state, int x, int y)> mouse;
        std::function<void(int direction, int x, int y)> wheel;
        std::function<void(int x, int y, bool buttonDown)> motion;
        std::function<void(bool entered)> entry;
        std::function<void(int width, int height)> resized;  // the framebuffer's new size
    };

    // Throws std::runtime_error if no window can be opened (no display).
    Presenter(int width, int height, const std::string& title);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    void setCallbacks(Callbacks callbacks) { callbacks_ = std::move(callbacks); }
    void setTitle(const std::string& title);
    void resize(int width, int height);
    // Whether held keys repeat their key-down callbacks.
    void setKeyRepeat(bool repeat) { keyRepeat_ = repeat; }
    // GLUT_ACTIVE_SHIFT | _CTRL | _ALT as of the last input event.
    int modifiers() const { return modifiers_; }
    bool shouldClose() const;
    void requestClose();
    void pollEvents();
    void waitBriefly();
    void present(const reference::Image& frame);
    // The window's current contents, read back through its own context.
    reference::Image screenshot();

private:
    struct Functions;
    void onKey(int key, int action, int mods);
    void onChar(unsigned codepoint);
    void cursor(int& x, int& y) const;
    void bindContext();

    GLFWwindow* window_ = nullptr;
    Functions* gl_ = nullptr;
    Callbacks callbacks_;
    int buttonsDown_ = 0;
    int modifiers_ = 0;
    bool keyRepeat_ = true;
    int lastKeyPressed_ = 0;
    std::map<int, unsigned char> keyChars_;  // the character each held key typed, for its release
};
