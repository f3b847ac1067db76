#pragma once
// Text and boxes drawn straight into an RGBA8 frame (rows bottom first), for what the window
// shows over a program's frame: the viewer's counts, GLUT's menus. Coordinates are window
// pixels from the top-left corner.
#include <reference/image.h>

#include <array>
#include <cstdint>
#include <string>

namespace glut {

using Rgba = std::array<std::uint8_t, 4>;

// `text` (lines split at '\n') with its top-left corner at (x, y), each font pixel `scale` wide.
void drawText(reference::Image& image, int x, int y, const std::string& text, Rgba color, int scale = 1);
// Width and height `text` takes at scale 1.
int textWidth(const std::string& text);
int textHeight(const std::string& text);
void fillBox(reference::Image& image, int x, int y, int width, int height, Rgba color);

}  // namespace glut
