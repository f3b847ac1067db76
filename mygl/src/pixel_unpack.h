#pragma once
// Client pixel data (glTexImage, glTexSubImage; glDrawPixels later) read into RGBA colours, as
// GL's pixel transfer does for colour formats.
#include <vector>

#include <glm/vec4.hpp>

#include "pixel_store.h"

namespace mygl {

// The width x height pixels at `pixels` under `modes`, each converted to RGBA: components to
// float (unsigned c / (2^b - 1), signed c / (2^(b-1) - 1) as the reference converts them),
// luminance to R, G and B, missing colour components 0 and a missing alpha 1. `format` is a
// colour format and `type` not GL_BITMAP (checked by the caller).
std::vector<glm::vec4> unpackImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                   const PixelStoreModes& modes);

// unpackImage for glDrawPixels: the reference keeps 32-bit integer components in a 16-bit
// texture before drawing them, so they are narrowed to 16 bits first.
std::vector<glm::vec4> unpackDrawnImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                        const PixelStoreModes& modes);

}  // namespace mygl
