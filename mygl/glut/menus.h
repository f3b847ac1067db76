#pragma once
// GLUT's menus as data: created, filled, changed and attached to mouse buttons by the program.
// The window shows them (menu_overlay.h); a headless run only keeps them.
#include <array>
#include <string>
#include <vector>

namespace glut {

struct MenuItem {
    std::string label;
    int value = 0;  // the callback's value, or the submenu's id
    bool submenu = false;
};

struct Menu {
    void (*callback)(int) = nullptr;
    std::vector<MenuItem> items;
    bool alive = true;
};

class Menus {
public:
    // A new menu (ids start at 1), which becomes the current one.
    int create(void (*callback)(int));
    void destroy(int id);
    int current() const { return current_; }
    void setCurrent(int id);
    // On the current menu; items are numbered from 1, as in GLUT.
    void add(const MenuItem& item);
    void change(int item, const MenuItem& replacement);
    void remove(int item);
    int itemCount() const;
    // The current menu opens on `button` (0, 1, 2); 0 detaches.
    void attach(int button, int id);
    int attached(int button) const;
    // nullptr for an unknown or destroyed id.
    const Menu* find(int id) const;

private:
    Menu* currentMenu(const char* call);
    std::vector<Menu> menus_;
    int current_ = 0;
    std::array<int, 3> attached_{};
};

}  // namespace glut
