#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace reference {

// An RGBA8 image, bottom row first (as GL and OSMesa hand it over).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Writes a PNG with the top row first (as image viewers expect). Throws std::runtime_error.
void writePng(const std::string& path, const Image& image);
Image readPng(const std::string& path);

}  // namespace reference
