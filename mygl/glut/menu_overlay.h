#pragma once
// An open GLUT menu in the window: a list drawn over the frame at the cursor. The button that
// opened it chooses an entry by being released over it; an entry with a submenu opens that
// list in its place, for a click to choose from.
#include <reference/image.h>

#include <optional>

#include "menus.h"

namespace glut {

struct MenuChoice {
    int menu;  // whose callback is called
    int value;
};

class MenuOverlay {
public:
    bool isOpen() const { return menu_ != 0; }
    void open(int menu, int x, int y);
    void hover(int x, int y) { hoverX_ = x, hoverY_ = y; }
    // The mouse button went up at (x, y): an entry's choice, or nothing (the list closes, or a
    // submenu opens in its place).
    std::optional<MenuChoice> release(const Menus& menus, int x, int y);
    void close() { menu_ = 0; }
    void draw(reference::Image& image, const Menus& menus) const;

private:
    // The item under (x, y), or -1.
    int itemAt(const Menu& menu, int x, int y) const;
    int width(const Menu& menu) const;

    int menu_ = 0;
    int x_ = 0, y_ = 0;
    int hoverX_ = -1, hoverY_ = -1;
};

}  // namespace glut
