#include "menus.h"

#include <cstdio>

namespace glut {

int Menus::create(void (*callback)(int)) {
    menus_.push_back({callback, {}, true});
    current_ = static_cast<int>(menus_.size());
    return current_;
}

const Menu* Menus::find(int id) const {
    if (id < 1 || id > static_cast<int>(menus_.size())) return nullptr;
    const Menu& menu = menus_[static_cast<std::size_t>(id - 1)];
    return menu.alive ? &menu : nullptr;
}

void Menus::destroy(int id) {
    if (!find(id)) return void(std::fprintf(stderr, "mygl glut: glutDestroyMenu(%d): no such menu\n", id));
    menus_[static_cast<std::size_t>(id - 1)] = {nullptr, {}, false};
    if (current_ == id) current_ = 0;
    for (int& a : attached_)
        if (a == id) a = 0;
}

void Menus::setCurrent(int id) {
    if (!find(id)) return void(std::fprintf(stderr, "mygl glut: glutSetMenu(%d): no such menu\n", id));
    current_ = id;
}

Menu* Menus::currentMenu(const char* call) {
    if (!find(current_)) {
        std::fprintf(stderr, "mygl glut: %s without a current menu\n", call);
        return nullptr;
    }
    return &menus_[static_cast<std::size_t>(current_ - 1)];
}

void Menus::add(const MenuItem& item) {
    if (Menu* menu = currentMenu(item.submenu ? "glutAddSubMenu" : "glutAddMenuEntry")) menu->items.push_back(item);
}

void Menus::change(int item, const MenuItem& replacement) {
    Menu* menu = currentMenu("glutChangeToMenuEntry/SubMenu");
    if (!menu) return;
    if (item < 1 || item > static_cast<int>(menu->items.size()))
        return void(std::fprintf(stderr, "mygl glut: no menu item %d to change\n", item));
    menu->items[static_cast<std::size_t>(item - 1)] = replacement;
}

void Menus::remove(int item) {
    Menu* menu = currentMenu("glutRemoveMenuItem");
    if (!menu) return;
    if (item < 1 || item > static_cast<int>(menu->items.size()))
        return void(std::fprintf(stderr, "mygl glut: no menu item %d to remove\n", item));
    menu->items.erase(menu->items.begin() + (item - 1));
}

int Menus::itemCount() const {
    const Menu* menu = find(current_);
    return menu ? static_cast<int>(menu->items.size()) : 0;
}

void Menus::attach(int button, int id) {
    if (button < 0 || button > 2)
        return void(std::fprintf(stderr, "mygl glut: no mouse button %d for a menu\n", button));
    if (id != 0 && !find(id)) return void(std::fprintf(stderr, "mygl glut: glutAttachMenu without a current menu\n"));
    attached_[static_cast<std::size_t>(button)] = id;
}

int Menus::attached(int button) const {
    return button >= 0 && button <= 2 ? attached_[static_cast<std::size_t>(button)] : 0;
}

}  // namespace glut
