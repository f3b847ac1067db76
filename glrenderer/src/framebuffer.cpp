#include "glrenderer/framebuffer.h"

#include <algorithm>
#include <stdexcept>

namespace glrenderer {

Framebuffer::Framebuffer(int width, int height) { resize(width, height); }

void Framebuffer::resize(int width, int height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("framebuffer size must be positive");
    width_ = width;
    height_ = height;
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    color_.assign(pixels, 0);
    depth_.assign(pixels, 0);
}

void Framebuffer::clearColor(std::uint32_t rgba) { std::fill(color_.begin(), color_.end(), rgba); }

void Framebuffer::clearDepth(std::uint32_t depth24) {
    std::fill(depth_.begin(), depth_.end(), depth24);
}

}  // namespace glrenderer
