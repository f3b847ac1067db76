#include "pixel_values.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "pixel_unpack.h"

namespace mygl {
namespace {

std::uint32_t valueAt(const std::uint8_t* p, GLenum type, bool swapBytes) {
    switch (type) {
    case GL_UNSIGNED_BYTE: return *p;
    case GL_BYTE: return static_cast<std::uint32_t>(static_cast<std::int32_t>(static_cast<std::int8_t>(*p)));
    case GL_UNSIGNED_SHORT: return readClientComponent<std::uint16_t>(p, swapBytes);
    case GL_SHORT:
        return static_cast<std::uint32_t>(static_cast<std::int32_t>(readClientComponent<std::int16_t>(p, swapBytes)));
    default: return readClientComponent<std::uint32_t>(p, swapBytes);  // GL_UNSIGNED_INT, GL_INT, GL_FLOAT
    }
}

float floatOf(std::uint32_t bits) { return std::bit_cast<float>(bits); }
std::int32_t signedOf(std::uint32_t bits) { return static_cast<std::int32_t>(bits); }

// The reference's C conversion of a float to an unsigned int (x86-64: through a 64-bit
// integer, so negative values wrap; out of range gives 0).
std::uint32_t toUnsigned(float f) {
    if (!(std::fabs(f) < 0x1p63f)) return 0;
    return static_cast<std::uint32_t>(static_cast<std::int64_t>(f));
}

// A value of `type` as the float Mesa's depth unpacking makes of it (macros.h conversions:
// zero kept zero for bytes and shorts).
float depthFloat(std::uint32_t value, GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<float>(value) / 255.0f;
    case GL_BYTE: {
        const std::int32_t b = signedOf(value);
        return b == 0 ? 0.0f : (2.0f * static_cast<float>(b) + 1.0f) * (1.0f / 255.0f);
    }
    case GL_UNSIGNED_SHORT: return static_cast<float>(value) * (1.0f / 65535.0f);
    case GL_SHORT: {
        const std::int32_t s = signedOf(value);
        return s == 0 ? 0.0f : (2.0f * static_cast<float>(s) + 1.0f) * (1.0f / 65535.0f);
    }
    case GL_UNSIGNED_INT: return static_cast<float>(static_cast<double>(value) * (1.0 / 4294967295.0));
    case GL_INT:
        return static_cast<float>(static_cast<double>(2.0f * static_cast<float>(signedOf(value)) + 1.0f) *
                                  (1.0 / 4294967294.0));
    default: return floatOf(value);
    }
}

// llvmpipe's write of a fragment depth to the 24-bit buffer: round(clamp(z) * (2^24 - 1)),
// ties to even, in float.
std::uint32_t depth24Of(float z) {
    return static_cast<std::uint32_t>(std::nearbyint(std::clamp(z, 0.0f, 1.0f) * 16777215.0f));
}

// llvmpipe's sampling of a 32-bit unorm depth texel: its top 23 bits as a float in [0, 1]
// (lp_build_unsigned_norm_to_float: the bits under the exponent of 1, minus 1, times 2^23 / (2^23 - 1)).
float sampledUnorm32(std::uint32_t texel) {
    const float top23 = std::bit_cast<float>((texel >> 9) | 0x3F800000u) - 1.0f;
    return top23 * static_cast<float>(8388608.0 / 8388607.0);
}

}  // namespace

void extractValues(const void* pixels, int width, int height, GLenum type, const PixelStoreModes& modes,
                   std::vector<std::uint32_t>& out) {
    out.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const ClientLayout layout = clientLayout(width, GL_STENCIL_INDEX, type, modes);
    const auto* base = static_cast<const std::uint8_t*>(pixels) + layout.firstByte;
    const std::size_t bytes = bytesOfType(type);
    if (type == GL_BITMAP) {
        // The reference reads a bitmap image's rows one after the other with no padding, as one
        // run of width x height bits (measured; GL pads rows to bytes). With skipped pixels it
        // starts at bit 2 x GL_UNPACK_SKIP_PIXELS of the first row (its first pixels measured;
        // the rest it reads from past its copy). Bits past the image's extent in GL's layout are
        // taken as 0.
        const auto* image = static_cast<const std::uint8_t*>(pixels);
        const std::size_t extent = layout.firstByte + static_cast<std::size_t>(height - 1) * layout.rowStride +
                                   (layout.firstBit + static_cast<std::size_t>(width) + 7) / 8;
        const auto skip = static_cast<std::size_t>(modes.skipPixels);
        const std::size_t first = (layout.firstByte - skip / 8) * 8 + 2 * skip;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const std::size_t bit = first + i;
            const unsigned inByte = bit % 8;
            out[i] = bit / 8 < extent ? (image[bit / 8] >> (modes.lsbFirst ? inByte : 7 - inByte)) & 1u : 0u;
        }
        return;
    }
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* row = base + static_cast<std::size_t>(y) * layout.rowStride;
        std::uint32_t* target = out.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
        for (int x = 0; x < width; ++x)
            target[x] = valueAt(row + static_cast<std::size_t>(x) * bytes, type, modes.swapBytes);
    }
}

std::uint32_t drawnDepth24(std::uint32_t value, GLenum type, const PixelModes& modes) {
    const bool transfer = modes.transfersDepth();
    // Mesa's texture store of the image (_mesa_unpack_depth_span): scale and bias, then clamp.
    float z = depthFloat(value, type);
    if (transfer) z = z * modes.depthScale + modes.depthBias;
    const bool clamps = transfer || type == GL_BYTE || type == GL_SHORT || type == GL_INT || type == GL_FLOAT;
    if (clamps) z = std::clamp(z, 0.0f, 1.0f);
    if (std::isnan(z)) z = 0.0f;  // NaN converts to 0 on the reference's way (measured)
    switch (type) {
    case GL_UNSIGNED_SHORT: {  // a 16-bit texture, copied as it is without a transfer
        const std::uint32_t texel = transfer ? static_cast<std::uint32_t>(z * 65535.0f) : value;
        return depth24Of(static_cast<float>(texel) * (1.0f / 65535.0f));
    }
    case GL_UNSIGNED_INT: {  // a 32-bit texture, copied as it is without a transfer
        std::uint32_t texel = value;
        if (transfer) {
            const double wide = static_cast<double>(z) * 4294967295.0;
            texel = wide >= 4294967295.0 ? 0xFFFFFFFFu : static_cast<std::uint32_t>(wide);
        }
        return depth24Of(sampledUnorm32(texel));
    }
    case GL_FLOAT: return depth24Of(z);  // a float texture
    default:
        return resampledDepth24(static_cast<std::uint32_t>(z * 16777215.0f));  // a 24-bit texture, truncated into it
    }
}

std::uint32_t resampledDepth24(std::uint32_t depth24) {
    return depth24Of(static_cast<float>(depth24) * (1.0f / 16777215.0f));
}

std::uint32_t drawnStencil(std::uint32_t value, GLenum type, const PixelModes& modes, const PixelMaps& maps) {
    std::uint32_t index = type == GL_FLOAT ? toUnsigned(floatOf(value)) : value;
    if (modes.mapStencil && type != GL_UNSIGNED_BYTE) {
        const std::vector<float>& map = maps.of(GL_PIXEL_MAP_S_TO_S);
        index = toUnsigned(map[index & static_cast<std::uint32_t>(map.size() - 1)]);
    }
    return index & 0xFFu;
}

glm::vec4 drawnIndexColor(std::uint32_t value, GLenum type, const PixelMaps& maps) {
    const std::uint32_t index = type == GL_FLOAT ? toUnsigned(floatOf(value)) : value;
    glm::vec4 c;
    for (int i = 0; i < 4; ++i) {
        const std::vector<float>& map = maps.of(static_cast<GLenum>(GL_PIXEL_MAP_I_TO_R + i));
        const float entry = map[index & static_cast<std::uint32_t>(map.size() - 1)];
        c[i] = std::isnan(entry) ? 0.0f : entry;  // (a NaN given to glPixelMap)
    }
    if (type == GL_FLOAT) return c;  // a float texture
    // Bytes first (the maps hold [0, 1]), then the texture of the type: signed types keep
    // them as snorm (x * max + 127) / 255 of 127 or 32767.
    const bool isSigned = type == GL_BYTE || type == GL_SHORT || type == GL_INT;
    const std::uint32_t max = type == GL_BYTE ? 127u : 32767u;
    for (int i = 0; i < 4; ++i) {
        const auto byte = static_cast<std::uint32_t>(std::nearbyint(c[i] * 255.0f));
        if (!isSigned) {
            c[i] = static_cast<float>(byte) * (1.0f / 255.0f);
        } else {
            c[i] = static_cast<float>((byte * max + 127u) / 255u) / static_cast<float>(max);
        }
    }
    return c;
}

}  // namespace mygl
