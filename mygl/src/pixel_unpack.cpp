#include "pixel_unpack.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace mygl {
namespace {

// Component i of type `type` at p, as a float.
float component(const std::uint8_t* p, GLenum type, bool swapBytes) {
    switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<float>(*p) / 255.0f;
    case GL_BYTE: return std::max(static_cast<float>(static_cast<std::int8_t>(*p)) / 127.0f, -1.0f);
    case GL_UNSIGNED_SHORT: return static_cast<float>(readClientComponent<std::uint16_t>(p, swapBytes)) / 65535.0f;
    case GL_SHORT:
        return std::max(static_cast<float>(readClientComponent<std::int16_t>(p, swapBytes)) / 32767.0f, -1.0f);
    case GL_UNSIGNED_INT: return static_cast<float>(readClientComponent<std::uint32_t>(p, swapBytes) / 4294967295.0);
    case GL_INT:
        return static_cast<float>(std::max(readClientComponent<std::int32_t>(p, swapBytes) / 2147483647.0, -1.0));
    case GL_FLOAT: return readClientComponent<float>(p, swapBytes);
    default: return 0.0f;
    }
}

// As component(), with 32-bit integers first narrowed to the 16 bits of the texture the
// reference's glDrawPixels keeps them in: unsigned rounded ((x * 65535 + 2^31 - 1) / (2^32 - 1)),
// signed by their top 16 bits; unsigned bytes as its sampler reads them, x * (1 / 255).
float drawnComponent(const std::uint8_t* p, GLenum type, bool swapBytes) {
    if (type == GL_UNSIGNED_BYTE) return static_cast<float>(*p) * (1.0f / 255.0f);
    if (type == GL_UNSIGNED_INT) {
        const std::uint64_t wide = readClientComponent<std::uint32_t>(p, swapBytes);
        return static_cast<float>((wide * 65535u + 0x7FFFFFFFu) / 0xFFFFFFFFu) / 65535.0f;
    }
    if (type == GL_INT) {
        const std::int32_t top = readClientComponent<std::int32_t>(p, swapBytes) >> 16;
        return std::max(static_cast<float>(top) / 32767.0f, -1.0f);
    }
    return component(p, type, swapBytes);
}

// As component(), as the reference's conversion to RGBA floats before a pixel transfer makes
// it (_mesa_unorm_to_float, _mesa_snorm_to_float: times the float reciprocal of the largest
// value, which for 32 bits is 2^32 or 2^31 as a float).
float transferComponent(const std::uint8_t* p, GLenum type, bool swapBytes) {
    const auto signedNorm = [](std::int32_t v, std::int32_t max) {
        return v <= -max ? -1.0f : static_cast<float>(v) * (1.0f / static_cast<float>(max));
    };
    switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<float>(*p) * (1.0f / 255.0f);
    case GL_BYTE: return signedNorm(static_cast<std::int8_t>(*p), 127);
    case GL_UNSIGNED_SHORT:
        return static_cast<float>(readClientComponent<std::uint16_t>(p, swapBytes)) * (1.0f / 65535.0f);
    case GL_SHORT: return signedNorm(readClientComponent<std::int16_t>(p, swapBytes), 32767);
    case GL_UNSIGNED_INT:
        return static_cast<float>(readClientComponent<std::uint32_t>(p, swapBytes)) *
               (1.0f / static_cast<float>(4294967295u));
    case GL_INT: return signedNorm(readClientComponent<std::int32_t>(p, swapBytes), 2147483647);
    default: return component(p, type, swapBytes);
    }
}

// One pixel's components (in the client's order) as RGBA.
glm::vec4 toRgba(const float* c, GLenum format) {
    switch (format) {
    case GL_RED: return {c[0], 0, 0, 1};
    case GL_GREEN: return {0, c[0], 0, 1};
    case GL_BLUE: return {0, 0, c[0], 1};
    case GL_ALPHA: return {0, 0, 0, c[0]};
    case GL_LUMINANCE: return {c[0], c[0], c[0], 1};
    case GL_LUMINANCE_ALPHA: return {c[0], c[0], c[0], c[1]};
    case GL_RGB: return {c[0], c[1], c[2], 1};
    case GL_BGR: return {c[2], c[1], c[0], 1};
    case GL_BGRA: return {c[2], c[1], c[0], c[3]};
    default: return {c[0], c[1], c[2], c[3]};
    }
}

template <float (*Component)(const std::uint8_t*, GLenum, bool)>
std::vector<glm::vec4> unpackWith(const void* pixels, int width, int height, GLenum format, GLenum type,
                                  const PixelStoreModes& modes) {
    std::vector<glm::vec4> out(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    if (!pixels) return out;
    const ClientLayout layout = clientLayout(width, format, type, modes);
    const int components = componentsOf(format);
    const std::size_t componentBytes = bytesOfType(type);
    const auto* base = static_cast<const std::uint8_t*>(pixels) + layout.firstByte;
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* p = base + static_cast<std::size_t>(y) * layout.rowStride;
        for (int x = 0; x < width; ++x) {
            float c[4] = {};
            for (int i = 0; i < components; ++i, p += componentBytes) c[i] = Component(p, type, modes.swapBytes);
            out[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
                toRgba(c, format);
        }
    }
    return out;
}

}  // namespace

std::vector<glm::vec4> unpackImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                   const PixelStoreModes& modes) {
    return unpackWith<component>(pixels, width, height, format, type, modes);
}

std::vector<glm::vec4> unpackImageForTransfer(const void* pixels, int width, int height, GLenum format, GLenum type,
                                              const PixelStoreModes& modes) {
    return unpackWith<transferComponent>(pixels, width, height, format, type, modes);
}

std::vector<glm::vec4> unpackDrawnImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                        const PixelStoreModes& modes) {
    return unpackWith<drawnComponent>(pixels, width, height, format, type, modes);
}

}  // namespace mygl
