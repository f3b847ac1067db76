#pragma once
// Client pixel data (glTexImage, glTexSubImage; glDrawPixels later) read into RGBA colours, as
// GL's pixel transfer does for colour formats.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/vec4.hpp>

#include "pixel_store.h"

namespace mygl {

// One component read from the program's memory at p, its bytes swapped under
// GL_UNPACK_SWAP_BYTES.
template <class T>
T readClientComponent(const std::uint8_t* p, bool swapBytes) {
    std::uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, p, sizeof(T));
    if (swapBytes) std::reverse(bytes, bytes + sizeof(T));
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
}

// The width x height pixels at `pixels` under `modes`, each converted to RGBA: components to
// float (unsigned c / (2^b - 1), signed c / (2^(b-1) - 1) as the reference converts them),
// luminance to R, G and B, missing colour components 0 and a missing alpha 1. `format` is a
// colour format and `type` not GL_BITMAP (checked by the caller).
std::vector<glm::vec4> unpackImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                   const PixelStoreModes& modes);

// unpackImage as the reference converts components before a pixel transfer (scale, bias, maps)
// on a texture image: times the float reciprocal of the type's largest value.
std::vector<glm::vec4> unpackImageForTransfer(const void* pixels, int width, int height, GLenum format, GLenum type,
                                              const PixelStoreModes& modes);

// unpackImage for glDrawPixels: the reference keeps 32-bit integer components in a 16-bit
// texture before drawing them, so they are narrowed to 16 bits first.
std::vector<glm::vec4> unpackDrawnImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                        const PixelStoreModes& modes);

}  // namespace mygl
