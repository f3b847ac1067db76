#pragma once
// The pixel modes (GL_PIXEL_MODE_BIT): glPixelTransfer's scales, biases, index shift and
// offset and map switches and glPixelZoom's factors; glPixelMap's tables (in no attribute
// group); the transfer applied to colours and depths as the reference applies it.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glad/gl.h>
#include <glm/vec4.hpp>

namespace mygl {

// glPixelMap's tables, in the order of the GL_PIXEL_MAP_* enums (one entry, 0, until set).
struct PixelMaps {
    static constexpr int kMaxSize = 256;  // GL_MAX_PIXEL_MAP_TABLE, the reference's
    static constexpr int kCount = 10;     // GL_PIXEL_MAP_I_TO_I .. GL_PIXEL_MAP_A_TO_A
    std::array<std::vector<float>, kCount> maps{[] {
        std::array<std::vector<float>, kCount> m;
        m.fill(std::vector<float>(1, 0.0f));
        return m;
    }()};
    const std::vector<float>& of(GLenum map) const { return maps[map - GL_PIXEL_MAP_I_TO_I]; }
    std::vector<float>& of(GLenum map) { return maps[map - GL_PIXEL_MAP_I_TO_I]; }
};

struct PixelModes {
    bool mapColor = false, mapStencil = false;
    int indexShift = 0, indexOffset = 0;
    glm::vec4 scale{1.0f}, bias{0.0f};
    float depthScale = 1.0f, depthBias = 0.0f;
    float zoomX = 1.0f, zoomY = 1.0f;
    bool operator==(const PixelModes&) const = default;

    // Whether colours go through scale, bias or maps on the way (the reference then reads and
    // writes colours through floats).
    bool transfersColor() const { return mapColor || scale != glm::vec4(1.0f) || bias != glm::vec4(0.0f); }
    bool transfersDepth() const { return depthScale != 1.0f || depthBias != 0.0f; }
    // Scale and bias (a separate multiply and add), then the R, G, B, A maps if on.
    glm::vec4 transferColor(glm::vec4 c, const PixelMaps& maps) const;
    // The same for glDrawPixels and glCopyPixels, for red and green: the reference samples
    // their maps from a 256 x 256 RGBA8 texture, entry floor(c * 256) (clamped to [0, 255]) of
    // 256 made of entry i * size / 256 of each map, in 8 bits. Blue and alpha are scaled and
    // biased only: the reference's second lookup does not read the maps (see pixel_rectangles.cpp).
    glm::vec4 transferDrawnColor(glm::vec4 c, const PixelMaps& maps) const;
    // Scale and bias, clamped to [0, 1].
    float transferDepth(float z) const;
    // A colour index on its way to an RGBA image (glTexImage, GL 1.1 3.6.3): the index shift as
    // a fixed-point shift and the offset added, then its integer part (floor) masked by each
    // I_TO_R .. I_TO_A map's size - 1 picks the map's entry. `value` holds the index of `type`
    // as extractValues keeps it (floats as their bits; NaN and infinities taken as 0).
    glm::vec4 indexToColor(std::uint32_t value, GLenum type, const PixelMaps& maps) const;
};

// The value of a pixel-mode query (glGet of GL_MAP_COLOR, GL_RED_SCALE, GL_PIXEL_MAP_*_SIZE,
// GL_ZOOM_X, ...), if `name` is one.
std::optional<double> pixelModeValue(const PixelModes& modes, const PixelMaps& maps, GLenum name);

}  // namespace mygl
