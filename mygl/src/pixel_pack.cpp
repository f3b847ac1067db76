#include "pixel_pack.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mygl {
namespace {

// c (in [0, 1] for integer types) as a component of `type`, rounded to nearest even.
void component(std::uint8_t* p, float c, GLenum type, bool swapBytes) {
    const double unit = std::clamp(static_cast<double>(c), 0.0, 1.0);
    switch (type) {
    case GL_UNSIGNED_BYTE: *p = static_cast<std::uint8_t>(std::nearbyint(unit * 255.0)); return;
    case GL_BYTE: *p = static_cast<std::uint8_t>(static_cast<std::int8_t>(std::nearbyint(unit * 127.0))); return;
    case GL_UNSIGNED_SHORT:
        return writeClientComponent(p, static_cast<std::uint16_t>(std::nearbyint(unit * 65535.0)), swapBytes);
    case GL_SHORT: return writeClientComponent(p, static_cast<std::int16_t>(std::nearbyint(unit * 32767.0)), swapBytes);
    case GL_UNSIGNED_INT:
        return writeClientComponent(p, static_cast<std::uint32_t>(std::nearbyint(unit * 4294967295.0)), swapBytes);
    case GL_INT:
        return writeClientComponent(p, static_cast<std::int32_t>(std::nearbyint(unit * 2147483647.0)), swapBytes);
    case GL_FLOAT: return writeClientComponent(p, c, swapBytes);
    default: return;
    }
}

// The components of `format` taken from colour c, in the client's order.
int fromRgba(const glm::vec4& c, GLenum format, float* out) {
    const float luminance = std::min(c.r + c.g + c.b, 1.0f);
    switch (format) {
    case GL_RED: out[0] = c.r; return 1;
    case GL_GREEN: out[0] = c.g; return 1;
    case GL_BLUE: out[0] = c.b; return 1;
    case GL_ALPHA: out[0] = c.a; return 1;
    case GL_LUMINANCE: out[0] = luminance; return 1;
    case GL_LUMINANCE_ALPHA: out[0] = luminance, out[1] = c.a; return 2;
    case GL_RGB: out[0] = c.r, out[1] = c.g, out[2] = c.b; return 3;
    case GL_BGR: out[0] = c.b, out[1] = c.g, out[2] = c.r; return 3;
    case GL_BGRA: out[0] = c.b, out[1] = c.g, out[2] = c.r, out[3] = c.a; return 4;
    default: out[0] = c.r, out[1] = c.g, out[2] = c.b, out[3] = c.a; return 4;
    }
}

// A texel's bytes as floats, times 1/255 as the reference converts them (not divided: 126 of the
// 256 values differ by an ulp).
glm::vec4 texelColor(std::uint32_t word, glrenderer::TextureBase base) {
    using glrenderer::TextureBase;
    auto channel = [word](int i) { return static_cast<float>((word >> (8 * i)) & 0xFFu) * (1.0f / 255.0f); };
    switch (base) {
    case TextureBase::Alpha: return {0, 0, 0, channel(3)};
    case TextureBase::Luminance: return {channel(0), 0, 0, 1};
    case TextureBase::LuminanceAlpha: return {channel(0), 0, 0, channel(3)};
    case TextureBase::Intensity: return {channel(0), 0, 0, 1};
    case TextureBase::Rgb: return {channel(0), channel(1), channel(2), 1};
    case TextureBase::Rgba: return {channel(0), channel(1), channel(2), channel(3)};
    }
    return {};
}

}  // namespace

void packImage(const std::vector<glm::vec4>& rgba, int width, int height, GLenum format, GLenum type,
               const PixelStoreModes& modes, void* out) {
    const ClientLayout layout = clientLayout(width, format, type, modes);
    const std::size_t componentBytes = bytesOfType(type);
    auto* base = static_cast<std::uint8_t*>(out) + layout.firstByte;
    for (int y = 0; y < height; ++y) {
        std::uint8_t* p = base + static_cast<std::size_t>(y) * layout.rowStride;
        for (int x = 0; x < width; ++x) {
            float c[4];
            const int n = fromRgba(
                rgba[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)],
                format, c);
            for (int i = 0; i < n; ++i, p += componentBytes) component(p, c[i], type, modes.swapBytes);
        }
    }
}

void packTexels(const std::vector<std::uint32_t>& texels, int width, int height, glrenderer::TextureBase base,
                GLenum format, GLenum type, const PixelStoreModes& modes, void* out) {
    std::vector<glm::vec4> rgba(texels.size());
    std::transform(texels.begin(), texels.end(), rgba.begin(), [base](std::uint32_t t) { return texelColor(t, base); });
    packImage(rgba, width, height, format, type, modes, out);
}

}  // namespace mygl
