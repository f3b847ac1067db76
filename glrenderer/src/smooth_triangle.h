#pragma once
#include <glm/vec4.hpp>

#include "fragment_paths.h"
#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "pixel_rect.h"
#include "window_vertex.h"

namespace glrenderer {

// A vertex of the quad the reference's draw module makes of a smooth point or line
// (draw_pipe_aapoint.c, draw_pipe_aaline.c): a window vertex and the extra generic varying
// its coverage shader reads.
struct SmoothVertex {
    WindowVertex v;
    glm::vec4 aa;
};

// What the coverage shader makes of the interpolated varying: false drops the fragment,
// else `factor` multiplies the fragment's alpha.
struct Coverage {
    bool kept;
    float factor;
};
using CoverageShader = Coverage (*)(const glm::vec4& aa);

// How a draw's smooth primitives shade, chosen once per draw.
struct SmoothShading {
    bool flat;              // one colour (`flatColor` of each primitive)
    bool replaceByModulate;  // GL_REPLACE drawn as GL_MODULATE of (1, 1, 1, alpha): see smoothFragmentKey
    bool textureAlpha;       // the texture has alpha (under replaceByModulate)
    bool textureColor;       // the texture has colour, not alpha alone (under replaceByModulate)
};

// The shading of a draw's smooth primitives.
SmoothShading smoothShading(const DrawState& state);

// Rasterizes one triangle of such a quad as llvmpipe rasterizes any triangle (snapped edges,
// its fill rule, planes anchored as its setup anchors them), interpolating colour, depth, fog,
// texture coordinates and `aa` with perspective, then multiplies each fragment's alpha by
// `coverage` of its `aa` and hands it to the fragment stage of `fragments` (a flat key: the
// colour reaches it per fragment). `flatColor` is the colour under flat shading.
// Under GL_REPLACE the alpha the coverage multiplies is the texture's: the fragment's colour
// becomes (1, 1, 1, coverage) for a texture with alpha and (1, 1, 1, alpha * coverage) for one
// without (an alpha texture keeps the fragment's red, green and blue), modulated by the texel,
// which gives GL_REPLACE's colour and the reference's alpha.
void drawSmoothTriangle(const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                        const SmoothShading& shading, const glm::vec4& flatColor, CoverageShader coverage, const FragmentChoice& fragments,
                        const PixelRect& drawable, Framebuffer& framebuffer, FragmentCounts& counts);

}  // namespace glrenderer
