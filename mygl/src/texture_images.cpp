#include "texture_images.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "pixel_unpack.h"
#include "pixel_values.h"

namespace mygl {

using glrenderer::TextureBase;

std::optional<TextureBase> textureBaseOf(GLint internalFormat) {
    switch (internalFormat) {
    case 1:
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16: return TextureBase::Luminance;
    case 2:
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16: return TextureBase::LuminanceAlpha;
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8:
    case GL_ALPHA12:
    case GL_ALPHA16: return TextureBase::Alpha;
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16: return TextureBase::Intensity;
    case 3:
    case GL_RGB:
    case GL_R3_G3_B2:
    case GL_RGB4:
    case GL_RGB5:
    case GL_RGB8:
    case GL_RGB10:
    case GL_RGB12:
    case GL_RGB16: return TextureBase::Rgb;
    case 4:
    case GL_RGBA:
    case GL_RGBA2:
    case GL_RGBA4:
    case GL_RGB5_A1:
    case GL_RGBA8:
    case GL_RGB10_A2:
    case GL_RGBA12:
    case GL_RGBA16: return TextureBase::Rgba;
    default: return std::nullopt;
    }
}

namespace {

std::uint32_t toByte(float c) { return static_cast<std::uint32_t>(std::nearbyint(std::clamp(c, 0.0f, 1.0f) * 255.0f)); }

// One colour as the texel of `base` stores it: luminance and intensity take R.
std::uint32_t texel(const glm::vec4& c, TextureBase base) {
    const std::uint32_t r = toByte(c.r), g = toByte(c.g), b = toByte(c.b), a = toByte(c.a);
    switch (base) {
    case TextureBase::Alpha: return a << 24;
    case TextureBase::Luminance: return r | r << 8 | r << 16 | 0xFFu << 24;
    case TextureBase::LuminanceAlpha: return r | r << 8 | r << 16 | a << 24;
    case TextureBase::Intensity: return r | r << 8 | r << 16 | r << 24;
    case TextureBase::Rgb: return r | g << 8 | b << 16 | 0xFFu << 24;
    case TextureBase::Rgba: return r | g << 8 | b << 16 | a << 24;
    }
    return 0;
}

}  // namespace

namespace {

// A GL_BITMAP index image's bits as GL 1.1 lays them out: each row from its own byte, rows
// padded to the alignment (not the one run of bits glDrawPixels' reference reads).
std::vector<std::uint32_t> bitmapIndices(const void* pixels, int width, int height, const PixelStoreModes& modes) {
    std::vector<std::uint32_t> out(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const ClientLayout layout = clientLayout(width, GL_COLOR_INDEX, GL_BITMAP, modes);
    const auto* image = static_cast<const std::uint8_t*>(pixels);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* row = image + layout.firstByte + static_cast<std::size_t>(y) * layout.rowStride;
        for (int x = 0; x < width; ++x) {
            const std::size_t bit = layout.firstBit + static_cast<std::size_t>(x);
            const unsigned inByte = bit % 8;
            out[static_cast<std::size_t>(y * width + x)] =
                (row[bit / 8] >> (modes.lsbFirst ? inByte : 7 - inByte)) & 1u;
        }
    }
    return out;
}

}  // namespace

UnpackedImage unpackTextureImage(const void* pixels, int width, int height, GLenum format, GLenum type,
                                 const PixelStoreModes& modes, bool forTransfer) {
    UnpackedImage image;
    if (format != GL_COLOR_INDEX || !pixels) {
        image.rgba = unpackImage(pixels, width, height, format, type, modes);
        image.transfers = pixels != nullptr;
        if (forTransfer && pixels)
            image.rgbaForTransfer = unpackImageForTransfer(pixels, width, height, format, type, modes);
        return image;
    }
    image.indexType = type;
    if (type == GL_BITMAP) {
        image.indices = bitmapIndices(pixels, width, height, modes);
    } else {
        extractValues(pixels, width, height, type, modes, image.indices);
    }
    return image;
}

std::vector<glm::vec4> transferredImage(const UnpackedImage& image, const PixelModes& modes, const PixelMaps& maps) {
    if (image.indexType != 0) {
        std::vector<glm::vec4> rgba(image.indices.size());
        std::transform(image.indices.begin(), image.indices.end(), rgba.begin(),
                       [&](std::uint32_t index) { return modes.indexToColor(index, image.indexType, maps); });
        return rgba;
    }
    if (!image.transfers || !modes.transfersColor()) return image.rgba;
    const std::vector<glm::vec4>& source = image.rgbaForTransfer.empty() ? image.rgba : image.rgbaForTransfer;
    std::vector<glm::vec4> rgba(source.size());
    std::transform(source.begin(), source.end(), rgba.begin(),
                   [&](const glm::vec4& c) { return modes.transferColor(c, maps); });
    return rgba;
}

std::vector<std::uint32_t> textureTexels(const std::vector<glm::vec4>& rgba, TextureBase base) {
    std::vector<std::uint32_t> texels(rgba.size());
    std::transform(rgba.begin(), rgba.end(), texels.begin(), [base](const glm::vec4& c) { return texel(c, base); });
    return texels;
}

void writeSubImage(TextureLevel& level, int x, int y, int width, int height, const std::vector<glm::vec4>& rgba) {
    for (int row = 0; row < height; ++row) {
        for (int column = 0; column < width; ++column) {
            const glm::vec4& c = rgba[static_cast<std::size_t>(row * width + column)];
            level.texels[static_cast<std::size_t>((y + row) * level.imageWidth + x + column)] = texel(c, level.base);
        }
    }
}

std::shared_ptr<const glrenderer::Texture> textureSnapshot(std::span<const TextureLevel> levels) {
    auto texture = std::make_shared<glrenderer::Texture>();
    texture->levelCount = static_cast<int>(levels.size());
    std::size_t total = 0;
    for (const TextureLevel& l : levels) total += l.texels.size();
    texture->texels.reserve(total);
    for (std::size_t i = 0; i < levels.size(); ++i) {
        texture->width[i] = static_cast<std::uint32_t>(levels[i].imageWidth);
        texture->height[i] = static_cast<std::uint32_t>(levels[i].imageHeight);
        texture->offset[i] = static_cast<std::uint32_t>(texture->texels.size());
        texture->texels.insert(texture->texels.end(), levels[i].texels.begin(), levels[i].texels.end());
    }
    texture->powerOfTwoWidth = std::has_single_bit(texture->width[0]);
    texture->powerOfTwoHeight = std::has_single_bit(texture->height[0]);
    return texture;
}

}  // namespace mygl
