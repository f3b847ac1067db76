#pragma once
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

namespace glrenderer {

// The texture coordinates of a bitmap's fragments under texturing, as the reference gives them:
// its fragment program reads the current coordinates as a constant unless something may make
// them vary (a texture matrix other than the identity, texture generation, or coordinates in
// the vertex format of the last draw); then it reads those of the quad the bitmap is drawn
// with: s from 0 to 1 left to right, t from 0 to 1 bottom to top, over the bitmap's rectangle
// (the 512 x 32 cache's, for bitmaps drawn together).
struct BitmapTexCoords {
    bool vary = false;
    glm::vec4 current{0, 0, 0, 1};  // when they do not vary
    bool operator==(const BitmapTexCoords&) const = default;
};

// A glBitmap: a rectangle of bits placed at a window pixel. Each set bit is a fragment of the
// raster color at the raster depth; clear bits leave the pixel alone.
struct Bitmap {
    int x = 0, y = 0;  // window pixel of the bitmap's lower-left bit (GL, y up)
    int width = 0, height = 0;
    std::span<const std::uint8_t> rows;  // bottom row first, most significant bit leftmost
    std::size_t rowStride = 0;           // bytes from one row to the next
    glm::vec4 color{1, 1, 1, 1};
    float z = 0;  // window depth in [0, 1]
    BitmapTexCoords texCoords;
};

}  // namespace glrenderer
