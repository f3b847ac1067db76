#include "bitmap_cache.h"

#include <cmath>

namespace mygl {

// Depths closer than this count as equal (the reference's Z_EPSILON).
constexpr float kDepthEpsilon = 1e-6f;

bool BitmapCache::accepts(int x, int y, int width, int height, const glm::vec4& color, float z) const {
    if (empty_) return true;
    const long px = static_cast<long>(x) - x_, py = static_cast<long>(y) - y_;
    return px >= 0 && px + width <= kWidth && py >= 0 && py + height <= kHeight && color == color_ &&
           !(std::fabs(z - z_) > kDepthEpsilon);
}

void BitmapCache::add(int x, int y, int width, int height, const std::uint8_t* rows, std::size_t stride,
                      const glm::vec4& color, float z) {
    if (empty_) {  // the first bitmap sits at the left, centred vertically
        x_ = x;
        y_ = y - (kHeight - height) / 2;
        color_ = color;
        z_ = z;
        empty_ = false;
    }
    const int px = x - x_, py = y - y_;
    for (int row = 0; row < height; ++row) {
        const std::uint8_t* source = rows + static_cast<std::size_t>(row) * stride;
        std::uint8_t* target = bits_.data() + static_cast<std::size_t>(py + row) * kStride;
        for (int bit = 0; bit < width; ++bit) {
            if (!(source[bit / 8] & (0x80 >> (bit % 8)))) continue;
            const int column = px + bit;
            target[column / 8] = static_cast<std::uint8_t>(target[column / 8] | (0x80 >> (column % 8)));
        }
    }
}

glrenderer::Bitmap BitmapCache::bitmap() const {
    glrenderer::Bitmap b;
    b.x = x_;
    b.y = y_;
    b.width = kWidth;
    b.height = kHeight;
    b.rows = bits_;
    b.rowStride = kStride;
    b.color = color_;
    b.z = z_;
    b.texCoords = texCoords_;
    return b;
}

void BitmapCache::clear() {
    empty_ = true;
    bits_.fill(0);
}

}  // namespace mygl
