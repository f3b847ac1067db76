#pragma once
// glPixelStore's modes for one direction (unpack: from the program's memory; pack: into it).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <glad/gl.h>

#include <mygl/gl12_enums.h>

namespace mygl {

struct PixelStoreModes {
    int alignment = 4;
    int rowLength = 0;  // 0: the image's width
    int skipPixels = 0, skipRows = 0;
    bool swapBytes = false, lsbFirst = false;
    bool operator==(const PixelStoreModes&) const = default;
};

// The formats and types of client pixel data GL 1.1 defines (with GL 1.2's BGR/BGRA).
bool isPixelFormat(GLenum format);
bool isPixelType(GLenum type);
// Components per pixel of `format` (1 for GL_COLOR_INDEX and the single channels).
int componentsOf(GLenum format);
// Bytes of one component of `type`; 0 for GL_BITMAP.
std::size_t bytesOfType(GLenum type);

// Where each row of a width x height image starts in the program's memory and its first pixel's
// offset in bits (for GL_BITMAP) or bytes, under `modes`.
struct ClientLayout {
    std::size_t rowStride;  // bytes from one row to the next
    std::size_t firstByte;  // of the first pixel of the first row
    unsigned firstBit;      // for GL_BITMAP: the first pixel's bit in its byte (0 = the first bit)
};
ClientLayout clientLayout(int width, GLenum format, GLenum type, const PixelStoreModes& modes);

// One component written into the program's memory at p, its bytes swapped under
// GL_PACK_SWAP_BYTES.
template <class T>
void writeClientComponent(std::uint8_t* p, T value, bool swapBytes) {
    std::uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (swapBytes) std::reverse(bytes, bytes + sizeof(T));
    std::memcpy(p, bytes, sizeof(T));
}

}  // namespace mygl
