#pragma once
// Colours written into the program's memory in a client format and type (glGetTexImage;
// glReadPixels later), as GL's pixel packing does.
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>
#include <glrenderer/texture.h>

#include "pixel_store.h"

namespace mygl {

// width x height RGBA colours written at `out` under `modes`: luminance as R + G + B clamped,
// each component converted to `type` (rounded to nearest for integers). `format` is a colour
// format and `type` not GL_BITMAP.
void packImage(const std::vector<glm::vec4>& rgba, int width, int height, GLenum format, GLenum type,
               const PixelStoreModes& modes, void* out);

// A texture image's texels as glGetTexImage returns them for base format `base` (luminance
// and intensity in R, the components the base lacks 0, alpha 1).
void packTexels(const std::vector<std::uint32_t>& texels, int width, int height, glrenderer::TextureBase base,
                GLenum format, GLenum type, const PixelStoreModes& modes, void* out);

}  // namespace mygl
