#include "glrenderer/framebuffer.h"

#include <algorithm>
#include <stdexcept>

#include "huge_pages.h"

namespace glrenderer {

Framebuffer::Framebuffer(int width, int height) { resize(width, height); }

void Framebuffer::resize(int width, int height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("framebuffer size must be positive");
    width_ = width;
    height_ = height;
    count_ = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    color_ = allocate(count_);
    depth_ = allocate(count_);
    accum_.clear();
    accum_.shrink_to_fit();
    stencil_ = allocate(count_);
    markWritten();
}

Framebuffer::Pixels Framebuffer::allocate(std::size_t count) {
    Pixels pixels(static_cast<std::uint32_t*>(allocatePages(count * sizeof(std::uint32_t), kAlignment)));
    std::fill_n(pixels.get(), count, 0u);
    return pixels;
}

std::span<std::int16_t> Framebuffer::accum() {
    if (accum_.empty()) accum_.assign(count_ * 4, 0);
    return accum_;
}

void Framebuffer::clearColor(std::uint32_t rgba) {
    std::fill_n(color_.get(), count_, rgba);
    markWritten();
}

void Framebuffer::clearDepth(std::uint32_t depth24) {
    std::fill_n(depth_.get(), count_, depth24);
    markWritten();
}

}  // namespace glrenderer
