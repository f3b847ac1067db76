#pragma once
// Texture images: converting unpacked RGBA colours into a level's texels, and the checks
// glTexImage and glTexSubImage share (texture_images.cpp).
#include <optional>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "pixel_modes.h"
#include "pixel_store.h"
#include "texture_state.h"

namespace mygl {

// A texture image as unpacked from the program's memory, before the pixel transfer (which a
// display list applies when it runs the call): RGBA colours, or for GL_COLOR_INDEX the indices
// of `indexType` as extractValues keeps them.
struct UnpackedImage {
    std::vector<glm::vec4> rgba;
    std::vector<glm::vec4> rgbaForTransfer;  // converted as the reference does before a transfer, when one may come
    std::vector<std::uint32_t> indices;
    GLenum indexType = 0;
    bool transfers = true;  // false for a null image: its texels are 0, with no transfer
};

// The width x height pixels at `pixels` (a colour format or GL_COLOR_INDEX, checked by the
// caller) under `modes`; `forTransfer`: a pixel transfer may come (it is on, or a list keeps the image).
UnpackedImage unpackTextureImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                 const PixelStoreModes& modes, bool forTransfer);

// The image's colours after the pixel transfer (GL 1.1, 3.8: as for glDrawPixels): colours
// scaled, biased and mapped under GL_MAP_COLOR; indices shifted, offset and mapped to RGBA.
std::vector<glm::vec4> transferredImage(const UnpackedImage& image, const PixelModes& modes, const PixelMaps& maps);

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
