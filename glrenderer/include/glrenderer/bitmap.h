#pragma once
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

namespace glrenderer {

// A glBitmap: a rectangle of bits placed at a window pixel. Each set bit is a fragment of the
// raster color at the raster depth; clear bits leave the pixel alone.
struct Bitmap {
    int x = 0, y = 0;  // window pixel of the bitmap's lower-left bit (GL, y up)
    int width = 0, height = 0;
    std::span<const std::uint8_t> rows;  // bottom row first, most significant bit leftmost
    std::size_t rowStride = 0;           // bytes from one row to the next
    glm::vec4 color{1, 1, 1, 1};
    float z = 0;  // window depth in [0, 1]
};

}  // namespace glrenderer
