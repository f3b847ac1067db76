#include "menu_overlay.h"

#include <algorithm>

#include "image_text.h"

namespace glut {
namespace {

constexpr int kItemHeight = 16, kPadding = 6;
constexpr Rgba kBackground{235, 235, 235, 255}, kHighlight{60, 90, 170, 255}, kText{0, 0, 0, 255},
    kHighlightText{255, 255, 255, 255}, kBorder{90, 90, 90, 255};

std::string shownLabel(const MenuItem& item) { return item.submenu ? item.label + "  >" : item.label; }

}  // namespace

void MenuOverlay::open(int menu, int x, int y) {
    menu_ = menu;
    x_ = x;
    y_ = y;
    hoverX_ = x;
    hoverY_ = y;
}

int MenuOverlay::width(const Menu& menu) const {
    int widest = 40;
    for (const MenuItem& item : menu.items) widest = std::max(widest, textWidth(shownLabel(item)));
    return widest + 2 * kPadding;
}

int MenuOverlay::itemAt(const Menu& menu, int x, int y) const {
    if (x < x_ || x >= x_ + width(menu) || y < y_) return -1;
    const int item = (y - y_) / kItemHeight;
    return item < static_cast<int>(menu.items.size()) ? item : -1;
}

std::optional<MenuChoice> MenuOverlay::release(const Menus& menus, int x, int y) {
    const Menu* menu = menus.find(menu_);
    const int item = menu ? itemAt(*menu, x, y) : -1;
    if (item < 0) {
        // Released where it opened (a click): the list stays for the next click.
        if (!(x == x_ && y == y_)) close();
        return std::nullopt;
    }
    const MenuItem& chosen = menu->items[static_cast<std::size_t>(item)];
    if (chosen.submenu) {
        open(chosen.value, x_ + width(*menu) - kPadding, y_ + item * kItemHeight);
        return std::nullopt;
    }
    const MenuChoice choice{menu_, chosen.value};
    close();
    return choice;
}

void MenuOverlay::draw(reference::Image& image, const Menus& menus) const {
    const Menu* menu = menus.find(menu_);
    if (!menu) return;
    const int w = width(*menu), h = static_cast<int>(menu->items.size()) * kItemHeight;
    fillBox(image, x_ - 1, y_ - 1, w + 2, h + 2, kBorder);
    fillBox(image, x_, y_, w, h, kBackground);
    const int hovered = itemAt(*menu, hoverX_, hoverY_);
    for (int i = 0; i < static_cast<int>(menu->items.size()); ++i) {
        const int top = y_ + i * kItemHeight;
        if (i == hovered) fillBox(image, x_, top, w, kItemHeight, kHighlight);
        drawText(image, x_ + kPadding, top + 4, shownLabel(menu->items[static_cast<std::size_t>(i)]),
                 i == hovered ? kHighlightText : kText);
    }
}

}  // namespace glut
