#include "image_text.h"

#include <stb/stb_easy_font.h>

#include <vector>

namespace glut {

void fillBox(reference::Image& image, int x, int y, int width, int height, Rgba color) {
    for (int row = y; row < y + height; ++row) {
        for (int column = x; column < x + width; ++column) {
            if (column < 0 || row < 0 || column >= image.width || row >= image.height) continue;
            const std::size_t index =
                (static_cast<std::size_t>(image.height - 1 - row) * static_cast<std::size_t>(image.width) +
                 static_cast<std::size_t>(column)) *
                4;
            for (std::size_t c = 0; c < 4; ++c) image.rgba[index + c] = color[c];
        }
    }
}

void drawText(reference::Image& image, int x, int y, const std::string& text, Rgba color, int scale) {
    std::vector<char> buffer(text.size() * 300 + 1000);
    const int quads = stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), nullptr, buffer.data(),
                                          static_cast<int>(buffer.size()));
    struct Corner {
        float x, y, z;
        unsigned char color[4];
    };
    const auto* corners = reinterpret_cast<const Corner*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
        const Corner* c = corners + 4 * q;  // an axis-aligned rectangle, y down from the top
        const int left = static_cast<int>(c[0].x) * scale, top = static_cast<int>(c[0].y) * scale;
        const int right = static_cast<int>(c[2].x) * scale, bottom = static_cast<int>(c[2].y) * scale;
        fillBox(image, x + left, y + top, right - left, bottom - top, color);
    }
}

int textWidth(const std::string& text) { return stb_easy_font_width(const_cast<char*>(text.c_str())); }
int textHeight(const std::string& text) { return stb_easy_font_height(const_cast<char*>(text.c_str())); }

}  // namespace glut
