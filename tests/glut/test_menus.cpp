// GLUT's menus as data and as the window's overlay: items numbered from 1, changes and removals,
// attachment to buttons, destroyed menus, and choosing by releasing the button over an entry
// (a submenu entry opens its list in place).
#include <gtest/gtest.h>

#include "menu_overlay.h"
#include "menus.h"

namespace {

int chosen = 0;
void record(int value) { chosen = value; }

}  // namespace

TEST(Menus, ItemsChangeAndAttachAsGlutNumbersThem) {
    glut::Menus menus;
    const int colors = menus.create(record);
    menus.add({"Red", 1, false});
    menus.add({"Green", 2, false});
    const int main = menus.create(record);
    EXPECT_EQ(main, colors + 1);
    EXPECT_EQ(menus.current(), main);
    menus.add({"Colours", colors, true});
    menus.add({"Quit", 9, false});
    menus.change(2, {"Exit", 10, false});
    menus.change(3, {"No such item", 0, false});  // refused, with a message
    EXPECT_EQ(menus.itemCount(), 2);
    EXPECT_EQ(menus.find(main)->items[1].label, "Exit");
    menus.remove(1);
    EXPECT_EQ(menus.itemCount(), 1);
    menus.attach(2, main);
    EXPECT_EQ(menus.attached(2), main);
    EXPECT_EQ(menus.attached(0), 0);
    menus.attach(7, main);  // no such button: refused
    menus.destroy(main);
    EXPECT_EQ(menus.find(main), nullptr);
    EXPECT_EQ(menus.attached(2), 0);
    EXPECT_EQ(menus.current(), 0);
    menus.add({"Orphan", 1, false});  // no current menu: refused
    EXPECT_EQ(menus.find(colors)->items.size(), 2u);
}

TEST(MenuOverlay, ReleasingOverAnEntryChoosesItAndASubmenuOpensInPlace) {
    glut::Menus menus;
    const int colors = menus.create(record);
    menus.add({"Red", 1, false});
    menus.add({"Green", 2, false});
    const int main = menus.create(record);
    menus.add({"Colours", colors, true});
    menus.add({"Quit", 9, false});

    glut::MenuOverlay overlay;
    overlay.open(main, 10, 20);
    // Items are 16 pixels high from the opening point.
    const auto quit = overlay.release(menus, 15, 20 + 16 + 5);
    ASSERT_TRUE(quit.has_value());
    EXPECT_EQ(quit->menu, main);
    EXPECT_EQ(quit->value, 9);
    EXPECT_FALSE(overlay.isOpen());

    overlay.open(main, 10, 20);
    EXPECT_FALSE(overlay.release(menus, 15, 25).has_value());  // the submenu entry
    EXPECT_TRUE(overlay.isOpen());
    reference::Image image{200, 120, std::vector<std::uint8_t>(200 * 120 * 4, 0)};
    overlay.draw(image, menus);
    int drawn = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) drawn += image.rgba[i + 3] != 0;
    EXPECT_GT(drawn, 200) << "the open list is drawn over the frame";

    overlay.hover(0, 0);
    EXPECT_FALSE(overlay.release(menus, 0, 0).has_value());  // outside: closes
    EXPECT_FALSE(overlay.isOpen());
    overlay.open(main, 10, 20);
    EXPECT_FALSE(overlay.release(menus, 10, 20).has_value());  // a click where it opened keeps it
    EXPECT_TRUE(overlay.isOpen());
}
