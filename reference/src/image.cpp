#include "reference/image.h"

#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace reference {

void writePng(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4) {
        throw std::runtime_error("writePng: image size and data do not match");
    }
    // Our rows run bottom-up; a PNG's run top-down: start at the last row, step backwards.
    const int stride = image.width * 4;
    const std::uint8_t* lastRow =
        image.rgba.data() + static_cast<std::size_t>(image.height - 1) * static_cast<std::size_t>(stride);
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, lastRow, -stride)) {
        throw std::runtime_error("could not write " + path);
    }
}

Image readPng(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    stbi_set_flip_vertically_on_load(1);
    std::uint8_t* pixels = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!pixels) throw std::runtime_error("could not read " + path);
    Image image{width, height,
                std::vector<std::uint8_t>(
                    pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)};
    stbi_image_free(pixels);
    return image;
}

}  // namespace reference
