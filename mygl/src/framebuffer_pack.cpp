#include "framebuffer_pack.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include <glrenderer/color_convert.h>

namespace mygl {
namespace {

// An 8-bit colour component as `type`: the reference converts unorm to unorm or snorm in
// integers, rounding to nearest (x * max + 127) / 255, and to float as x / 255.
void putByteComponent(std::uint8_t* p, std::uint32_t c, GLenum type, bool swap) {
    const auto rescaled = [c](std::int64_t max) { return (static_cast<std::int64_t>(c) * max + 127) / 255; };
    switch (type) {
    case GL_UNSIGNED_BYTE: return writeClientComponent(p, static_cast<std::uint8_t>(c), swap);
    case GL_BYTE: return writeClientComponent(p, static_cast<std::int8_t>(rescaled(127)), swap);
    case GL_UNSIGNED_SHORT: return writeClientComponent(p, static_cast<std::uint16_t>(c * 257u), swap);
    case GL_SHORT: return writeClientComponent(p, static_cast<std::int16_t>(rescaled(32767)), swap);
    case GL_UNSIGNED_INT: return writeClientComponent(p, c * 16843009u, swap);
    case GL_INT: return writeClientComponent(p, static_cast<std::int32_t>(rescaled(2147483647)), swap);
    case GL_FLOAT: return writeClientComponent(p, static_cast<float>(c) * (1.0f / 255.0f), swap);
    default: return;
    }
}

// A float component (luminance formats and transferred colours go through floats) as `type`:
// unsigned types clamp below 0 and above 1, signed ones below -1 and above 1, floats keep
// it; in range, v * max in float rounded to nearest, 32-bit results wrapping as the
// reference's do (1 reads as INT_MIN and 0).
void putFloatComponent(std::uint8_t* p, float v, GLenum type, bool swap) {
    const bool isSigned = type == GL_BYTE || type == GL_SHORT || type == GL_INT;
    const float low = isSigned ? -1.0f : 0.0f;
    const auto scaled = [v, low](float max) {
        if (v < low) return std::llrint(low * max);
        return v > 1.0f ? static_cast<long long>(max) : std::llrint(v * max);
    };
    switch (type) {
    case GL_UNSIGNED_BYTE: return writeClientComponent(p, static_cast<std::uint8_t>(scaled(255.0f)), swap);
    case GL_BYTE: return writeClientComponent(p, static_cast<std::int8_t>(scaled(127.0f)), swap);
    case GL_UNSIGNED_SHORT: return writeClientComponent(p, static_cast<std::uint16_t>(scaled(65535.0f)), swap);
    case GL_SHORT: return writeClientComponent(p, static_cast<std::int16_t>(scaled(32767.0f)), swap);
    case GL_UNSIGNED_INT:
        return writeClientComponent(p, v > 1.0f ? 4294967295u : static_cast<std::uint32_t>(scaled(4294967295.0f)),
                                    swap);
    case GL_INT:
        return writeClientComponent(p, v > 1.0f ? 2147483647 : static_cast<std::int32_t>(scaled(2147483647.0f)), swap);
    case GL_FLOAT: return writeClientComponent(p, v, swap);
    default: return;
    }
}

// A depth as `type`, with the reference's depth packing: truncation for bytes and shorts
// (signed ones as (trunc(z * 2^n - 1) - 1) / 2), rounding for unsigned shorts, the 24 bits
// replicated into 32 for unsigned ints (its fast path: without swapped bytes or a depth
// transfer; otherwise through the float, truncated). `z` is the depth24's float, transferred.
void putDepth(std::uint8_t* p, std::uint32_t depth24, float z, bool fastPath, GLenum type, bool swap) {
    switch (type) {
    case GL_UNSIGNED_BYTE:
        return writeClientComponent(p, static_cast<std::uint8_t>(static_cast<int>(z * 255.0f)), swap);
    case GL_BYTE:
        return writeClientComponent(p, static_cast<std::int8_t>((static_cast<int>(z * 255.0f) - 1) / 2), swap);
    case GL_UNSIGNED_SHORT: return writeClientComponent(p, static_cast<std::uint16_t>(std::lrint(z * 65535.0f)), swap);
    case GL_SHORT:
        return writeClientComponent(p, static_cast<std::int16_t>((static_cast<int>(z * 65535.0f) - 1) / 2), swap);
    case GL_UNSIGNED_INT:
        if (!fastPath)
            return writeClientComponent(p, static_cast<std::uint32_t>(static_cast<double>(z) * 4294967295.0), swap);
        return writeClientComponent(p, (depth24 << 8) | (depth24 >> 16), swap);
    case GL_INT: return writeClientComponent(p, static_cast<std::int32_t>(2147483647.0 * static_cast<double>(z)), swap);
    case GL_FLOAT: return writeClientComponent(p, z, swap);
    default: return;
    }
}

// Calls writePixel(p, index) for each source pixel, p where its first component goes.
template <class WritePixel>
void packRows(int width, int height, GLenum format, GLenum type, const PixelStoreModes& modes, const PackTarget& target,
              WritePixel writePixel) {
    const ClientLayout layout = clientLayout(target.fullWidth, format, type, modes);
    const std::size_t pixelBytes = bytesOfType(type) * static_cast<std::size_t>(componentsOf(format));
    auto* first = static_cast<std::uint8_t*>(target.pixels) + layout.firstByte + target.skipRows * layout.rowStride +
                  target.skipColumns * pixelBytes;
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
        std::uint8_t* p = first + y * layout.rowStride;
        for (std::size_t x = 0; x < static_cast<std::size_t>(width); ++x, p += pixelBytes) {
            writePixel(p, y * static_cast<std::size_t>(width) + x);
        }
    }
}

// Which bytes of an RGBA8 word `format` takes, in the client's order (-1 ends the list).
std::array<int, 4> byteOrderOf(GLenum format) {
    switch (format) {
    case GL_RED: return {0, -1, -1, -1};
    case GL_GREEN: return {1, -1, -1, -1};
    case GL_BLUE: return {2, -1, -1, -1};
    case GL_ALPHA: return {3, -1, -1, -1};
    case GL_RGB: return {0, 1, 2, -1};
    case GL_BGR: return {2, 1, 0, -1};
    case GL_BGRA: return {2, 1, 0, 3};
    default: return {0, 1, 2, 3};
    }
}

}  // namespace

void packColors(std::span<const std::uint32_t> rgba8, int width, int height, GLenum format, GLenum type,
                const PixelStoreModes& modes, const PixelModes& pixel, const PixelMaps& maps,
                const PackTarget& target) {
    const bool swap = modes.swapBytes;
    const std::size_t step = bytesOfType(type);
    if (pixel.transfersColor()) {
        // Through floats (each byte times 1/255) and the transfer, unclamped; luminance formats
        // clamp every component to [0, 1] (alpha too), the sum again.
        const std::array<int, 4> order = byteOrderOf(format);
        packRows(width, height, format, type, modes, target, [&](std::uint8_t* p, std::size_t i) {
            glm::vec4 c;
            for (int k = 0; k < 4; ++k) c[k] = static_cast<float>((rgba8[i] >> (8 * k)) & 0xFFu) * (1.0f / 255.0f);
            c = pixel.transferColor(c, maps);
            if (format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA) {
                const auto unit = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
                putFloatComponent(p, std::min(unit(c.r) + unit(c.g) + unit(c.b), 1.0f), type, swap);
                if (format == GL_LUMINANCE_ALPHA) putFloatComponent(p + step, unit(c.a), type, swap);
                return;
            }
            for (int k = 0; k < 4 && order[static_cast<std::size_t>(k)] >= 0; ++k, p += step) {
                putFloatComponent(p, c[order[static_cast<std::size_t>(k)]], type, swap);
            }
        });
        return;
    }
    if (format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA) {
        // The reference goes through floats (each byte times 1/255, summed red first, clamped).
        packRows(width, height, format, type, modes, target, [&](std::uint8_t* p, std::size_t i) {
            const auto channel = [word = rgba8[i]](int c) {
                return static_cast<float>((word >> (8 * c)) & 0xFFu) * (1.0f / 255.0f);
            };
            putFloatComponent(p, std::min(channel(0) + channel(1) + channel(2), 1.0f), type, swap);
            if (format == GL_LUMINANCE_ALPHA) putFloatComponent(p + step, channel(3), type, swap);
        });
        return;
    }
    const std::array<int, 4> order = byteOrderOf(format);
    packRows(width, height, format, type, modes, target, [&](std::uint8_t* p, std::size_t i) {
        for (int c = 0; c < 4 && order[static_cast<std::size_t>(c)] >= 0; ++c, p += step) {
            putByteComponent(p, (rgba8[i] >> (8 * order[static_cast<std::size_t>(c)])) & 0xFFu, type, swap);
        }
    });
}

void packDepths(std::span<const std::uint32_t> depth24, int width, int height, GLenum type,
                const PixelStoreModes& modes, const PixelModes& pixel, const PackTarget& target) {
    const bool transfer = pixel.transfersDepth();
    const bool fastPath = !transfer && !modes.swapBytes;
    packRows(width, height, GL_DEPTH_COMPONENT, type, modes, target, [&](std::uint8_t* p, std::size_t i) {
        float z = static_cast<float>(depth24[i]) / static_cast<float>(glrenderer::kDepthMax24);
        if (transfer) z = pixel.transferDepth(z);
        putDepth(p, depth24[i], z, fastPath, type, modes.swapBytes);
    });
}

void packStencils(std::span<const std::uint32_t> stencil, int width, int height, GLenum type,
                  const PixelStoreModes& modes, const PixelModes& pixel, const PixelMaps& maps,
                  const PackTarget& target) {
    const bool swap = modes.swapBytes;
    const std::vector<float>& map = maps.of(GL_PIXEL_MAP_S_TO_S);
    packRows(width, height, GL_STENCIL_INDEX, type, modes, target, [&](std::uint8_t* p, std::size_t i) {
        std::int64_t value = stencil[i];
        value =
            pixel.indexShift >= 0 ? value << std::min(pixel.indexShift, 32) : value >> std::min(-pixel.indexShift, 32);
        value += pixel.indexOffset;
        if (pixel.mapStencil)
            value = static_cast<std::int64_t>(map[static_cast<std::size_t>(value) & (map.size() - 1)]);
        switch (type) {
        case GL_UNSIGNED_BYTE:
        case GL_BYTE: return writeClientComponent(p, static_cast<std::uint8_t>(value), swap);
        case GL_UNSIGNED_SHORT:
        case GL_SHORT: return writeClientComponent(p, static_cast<std::uint16_t>(value), swap);
        case GL_FLOAT: return writeClientComponent(p, static_cast<float>(value), swap);
        default: return writeClientComponent(p, static_cast<std::uint32_t>(value), swap);
        }
    });
}

}  // namespace mygl
