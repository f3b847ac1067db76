#pragma once
// The reference's bitmap cache (Mesa's st_cb_bitmap.c): glBitmap calls of one colour and depth
// whose bits fit in a 512 x 32 window area are gathered and drawn as one, when the next bitmap
// does not fit, or at the next draw, clear, flush or read. It is drawn with the state in force
// at the last glBitmap call (the reference validates its state there, and flushes the cache
// before validating at a draw or read): a glBitmap that does not fit draws the cache with the
// state of that moment, a draw after a state change with the state before the change
// (measured: docs/probes/bitmap_cache_state_probe.c).
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>
#include <glrenderer/bitmap.h>
#include <glrenderer/draw_state.h>

namespace mygl {

class BitmapCache {
public:
    static constexpr int kWidth = 512, kHeight = 32;

    bool empty() const { return empty_; }
    // Whether a bitmap of this size can be cached at all.
    static bool cacheable(int width, int height) { return width <= kWidth && height <= kHeight; }
    // Whether it can join what is cached (always when the cache is empty).
    bool accepts(int x, int y, int width, int height, const glm::vec4& color, float z) const;
    // Adds a cacheable bitmap that the cache accepts; `rows` as glBitmap's, `stride` bytes apart.
    void add(int x, int y, int width, int height, const std::uint8_t* rows, std::size_t stride, const glm::vec4& color,
             float z);
    // The whole cache as one bitmap to draw; then clear().
    glrenderer::Bitmap bitmap() const;
    void clear();
    // The state of the last glBitmap call, which the cache is drawn with, and its texture
    // coordinates.
    void setDrawState(const glrenderer::DrawState& state, const glrenderer::BitmapTexCoords& texCoords) {
        drawState_ = state;
        texCoords_ = texCoords;
    }
    const glrenderer::DrawState& drawState() const { return drawState_; }

private:
    static constexpr std::size_t kStride = kWidth / 8;
    bool empty_ = true;
    int x_ = 0, y_ = 0;
    glm::vec4 color_{};
    float z_ = 0;
    std::array<std::uint8_t, kStride * kHeight> bits_{};
    glrenderer::DrawState drawState_;
    glrenderer::BitmapTexCoords texCoords_;
};

}  // namespace mygl
