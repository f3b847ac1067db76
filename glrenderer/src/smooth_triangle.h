#pragma once
#include <glm/vec4.hpp>

#include "fragment_paths.h"
#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "pixel_rect.h"
#include "tiled_primitive.h"
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

// The colour a fragment hands on, from its interpolated colour and its coverage.
using CoveredColor = glm::vec4 (*)(const glm::vec4& color, float coverage);

// How a draw's smooth primitives shade, chosen once per draw.
struct SmoothShading {
    bool flat;  // one colour (`flatColor` of each primitive)
    CoveredColor covered;
};

// The shading of a draw's smooth primitives.
SmoothShading smoothShading(const DrawState& state);

// Queues for the tiles one triangle of such a quad, to be rasterized as llvmpipe rasterizes any triangle (snapped
// edges, its fill rule, planes anchored as its setup anchors them), interpolating colour, depth, fog, texture
// coordinates and `aa` with perspective, then multiplies each fragment's alpha by `coverage` of its `aa` and hands it
// to the fragment stage of `fragments` (a flat key: the colour reaches it per fragment). `flatColor` is the colour
// under flat shading. The shading's `covered` gives the colour the stage takes (smoothShading). The fragments lie in
// `drawable`.
void queueSmoothTriangle(const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                         const SmoothShading& shading, const glm::vec4& flatColor, CoverageShader coverage,
                         const FragmentChoice& fragments, const PixelRect& drawable, PrimitiveQueue& queue);

}  // namespace glrenderer
