#pragma once
// Texture images: converting unpacked RGBA colours into a level's texels, and the checks
// glTexImage and glTexSubImage share (texture_images.cpp).
#include <optional>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "texture_state.h"

namespace mygl {

// The base format of a GL 1.1 internal format (1-4, the symbolic and the sized ones), or
// nullopt for another value.
std::optional<glrenderer::TextureBase> textureBaseOf(GLint internalFormat);

// An image's texels in RGBA8 as the reference stores and samples them for `base` (clamped, each
// channel rounded to nearest even of c * 255).
std::vector<std::uint32_t> textureTexels(const std::vector<glm::vec4>& rgba, glrenderer::TextureBase base);

// glTexSubImage's rectangle of `rgba` (width x height) written into the level's image at (x, y).
void writeSubImage(TextureLevel& level, int x, int y, int width, int height, const std::vector<glm::vec4>& rgba);

// The pipeline's texture of levels [0, levelCount) of `levels` (defined, each half the one before).
std::shared_ptr<const glrenderer::Texture> textureSnapshot(std::span<const TextureLevel> levels);

}  // namespace mygl
