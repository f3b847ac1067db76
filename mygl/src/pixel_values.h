#pragma once
// The images of glDrawPixels that are not colours (GL_DEPTH_COMPONENT, GL_STENCIL_INDEX,
// GL_COLOR_INDEX), turned into what the reference's drawing takes from them: 24-bit window
// depths, stencil values, colours. docs/reference-rules.md, "Pixel rectangles", has the rules.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "pixel_modes.h"
#include "pixel_store.h"

namespace mygl {

// The width x height values (bottom row first) of a one-component image at `pixels` under
// `modes`, each as 32 bits: unsigned types zero-extended, signed ones sign-extended, floats as
// their bits, GL_BITMAP's bits as 0 or 1. Kept in `out` (reused: no allocation once it is large
// enough).
void extractValues(const void* pixels, int width, int height, GLenum type, const PixelStoreModes& modes,
                   std::vector<std::uint32_t>& out);

// A depth value of `type` (as extractValues keeps it) as the 24-bit depth the reference's
// image writes: through the texture it keeps the image in (16 bits for unsigned shorts, 32 for
// unsigned ints, float for floats, 24 for the others) after the depth scale and bias.
std::uint32_t drawnDepth24(std::uint32_t value, GLenum type, const PixelModes& modes);

// A 24-bit depth as the reference's drawing writes it back from a 24-bit texture (glCopyPixels
// of depth): sampled as z * (1 / (2^24 - 1)) in float, then rounded to 24 bits again, which
// moves some odd values up by one.
std::uint32_t resampledDepth24(std::uint32_t depth24);

// A stencil index of `type` as the reference's image writes it: through GL_MAP_STENCIL (not
// for unsigned bytes, which it copies as they are), never index shift and offset (measured);
// its low 8 bits (floats truncated).
std::uint32_t drawnStencil(std::uint32_t value, GLenum type, const PixelModes& modes, const PixelMaps& maps);

// A colour index of `type` as the reference's image colours it: the I_TO_R, G, B, A maps
// (index masked by each map's size; no index shift and offset: measured), in bytes, then kept
// in the texture of the type (snorm for signed types; floats take the maps as they are).
glm::vec4 drawnIndexColor(std::uint32_t value, GLenum type, const PixelMaps& maps);

}  // namespace mygl
