#pragma once
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

#include "glrenderer/texture.h"

namespace glrenderer {

// A glDrawPixels image: width x height colours (bottom row first) with its lower-left corner at
// a window pixel, zoomed by any factors. The reference draws it as a fan of two triangles from
// (x, y) to (x + width * zoomX, y + height * zoomY), textured with the image (nearest texel,
// clamped, replacing the colour), so that is how it is drawn here: coverage, the texel each
// pixel takes (ties at zoom 0.5 fall by the planes' float rounding) and depth come out the same.
struct PixelImage {
    int x = 0, y = 0;
    int width = 0, height = 0;
    float zoomX = 1, zoomY = 1;
    std::span<const glm::vec4> colors;
    // Or, with no colours, the image as fragment colour words already (RGBA8, red in the low
    // byte), or as 24-bit window depths or stencil values (`use`).
    std::span<const std::uint32_t> words;
    // Depth images colour their fragments with `color` and go through the draw's fragment
    // operations (fog and texturing aside, as the reference's depth program); stencil images
    // write their values under the stencil write mask and the scissor alone, no colour.
    TexelUse use = TexelUse::Color;
    glm::vec4 color{1.0f};
    // The current texture coordinates: a colour image under texturing is textured with them,
    // as a constant (ImageTexturing).
    glm::vec4 texCoord{0.0f, 0.0f, 0.0f, 1.0f};
    float z = 0;  // window depth in [0, 1] of every fragment
    // glCopyPixels' texture holds the rows top first, with t = 0 at the quad's top: the same
    // texels, but a centre on a texel boundary may fall the other way.
    bool topRowFirst = false;
};

}  // namespace glrenderer
