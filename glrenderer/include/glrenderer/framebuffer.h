#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <vector>

namespace glrenderer {

// RGBA8 color, 24-bit depth and 8-bit stencil, row 0 at the bottom (the layout of glReadPixels and OSMesa).
class Framebuffer {
public:
    Framebuffer(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    void resize(int width, int height);

    // Packed R, G, B, A bytes in memory order, one std::uint32_t per pixel. A Pipeline keeps
    // track of what it writes; anyone else writing pixels through color() or depth() calls
    // markWritten() afterwards.
    std::span<std::uint32_t> color() { return {color_.get(), count_}; }
    std::span<const std::uint32_t> color() const { return {color_.get(), count_}; }
    // Depth as an unsigned 24-bit integer (0 = near, 0xFFFFFF = far) per pixel.
    std::span<std::uint32_t> depth() { return {depth_.get(), count_}; }
    std::span<const std::uint32_t> depth() const { return {depth_.get(), count_}; }

    // The accumulation buffer: R, G, B, A signed 16-bit words per pixel (the reference's
    // GL_RGBA16_SNORM), allocated zeroed at the first use, as a program that never calls glAccum
    // pays nothing for it.
    std::span<std::int16_t> accum();
    // Stencil values in the low byte of a word per pixel (the fragment stage's lanes are words).
    std::span<std::uint32_t> stencil() { return {stencil_.get(), count_}; }
    std::span<const std::uint32_t> stencil() const { return {stencil_.get(), count_}; }

    void clearColor(std::uint32_t rgba);
    void clearDepth(std::uint32_t depth24);

    // Changes whenever pixels are written other than by a Pipeline: resize, clearColor,
    // clearDepth, markWritten.
    std::uint64_t writeGeneration() const { return writeGeneration_; }
    void markWritten() { ++writeGeneration_; }

private:
    // Rows start on cache lines as far as the width allows, and the buffers always do: threads
    // drawing neighbouring tiles must not write the same cache line (false sharing).
    static constexpr std::size_t kAlignment = 64;
    // Each buffer in huge pages where the kernel grants them (the tiles read it a tile at a time).
    struct FreePixels {
        void operator()(std::uint32_t* pixels) const { std::free(pixels); }
    };
    using Pixels = std::unique_ptr<std::uint32_t[], FreePixels>;
    static Pixels allocate(std::size_t count);

    int width_ = 0;
    int height_ = 0;
    std::size_t count_ = 0;
    std::uint64_t writeGeneration_ = 0;
    Pixels color_;
    Pixels depth_;
    std::vector<std::int16_t> accum_;
    Pixels stencil_;
};

}  // namespace glrenderer
