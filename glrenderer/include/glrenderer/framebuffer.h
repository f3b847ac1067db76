#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace glrenderer {

// RGBA8 color and 24-bit depth, row 0 at the bottom (the layout of glReadPixels and OSMesa).
class Framebuffer {
public:
    Framebuffer(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    void resize(int width, int height);

    // Packed R, G, B, A bytes in memory order, one std::uint32_t per pixel.
    std::span<std::uint32_t> color() { return color_; }
    std::span<const std::uint32_t> color() const { return color_; }
    // Depth as an unsigned 24-bit integer (0 = near, 0xFFFFFF = far) per pixel.
    std::span<std::uint32_t> depth() { return depth_; }
    std::span<const std::uint32_t> depth() const { return depth_; }

    void clearColor(std::uint32_t rgba);
    void clearDepth(std::uint32_t depth24);

private:
    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint32_t> color_;
    std::vector<std::uint32_t> depth_;
};

}  // namespace glrenderer
