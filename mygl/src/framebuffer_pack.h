#pragma once
// The framebuffer's colours (RGBA8) and depths (24 bits) written into the program's memory in
// any GL 1.1 format and type, converted as the reference's glReadPixels converts them
// (measured: docs/probes/read_pixels_probe.c, rules in docs/reference-rules.md).
#include <cstdint>
#include <span>

#include "pixel_modes.h"
#include "pixel_store.h"

namespace mygl {

// Where a read rectangle lands in the program's memory: its full width (for the row layout)
// and the offset of the part inside the window, which alone is written.
struct PackTarget {
    void* pixels;
    int fullWidth;
    std::size_t skipColumns, skipRows;
};

// width x height RGBA8 words (red in the low byte), bottom row first, through the pixel
// transfer of `pixel`. `format` is a colour format other than GL_COLOR_INDEX, `type` not GL_BITMAP.
void packColors(std::span<const std::uint32_t> rgba8, int width, int height, GLenum format, GLenum type,
                const PixelStoreModes& modes, const PixelModes& pixel, const PixelMaps& maps, const PackTarget& target);
// width x height 24-bit depths, bottom row first, through the depth scale and bias; `type` not
// GL_BITMAP.
void packDepths(std::span<const std::uint32_t> depth24, int width, int height, GLenum type,
                const PixelStoreModes& modes, const PixelModes& pixel, const PackTarget& target);

// width x height stencil values, bottom row first, through the index shift and offset and
// GL_MAP_STENCIL, as indices of `type` (integers as they are, GL_FLOAT as a float).
void packStencils(std::span<const std::uint32_t> stencil, int width, int height, GLenum type,
                  const PixelStoreModes& modes, const PixelModes& pixel, const PixelMaps& maps,
                  const PackTarget& target);

}  // namespace mygl
