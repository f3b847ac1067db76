#pragma once
#include <span>

#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/hit_range.h"
#include "glrenderer/stats.h"
#include "clip_vertex.h"
#include "feedback_output.h"
#include "line_stipple.h"
#include "tiled_primitive.h"

namespace glrenderer {

// Draws a batch of GL_POINTS, GL_LINES, GL_LINE_STRIP or GL_LINE_LOOP vertices (clip space) as
// the reference does: points are kept or dropped by their center, segments (i, i+1) in
// submission order, a loop closed by (last, first), each clipped to the view volume and
// rasterized with the reference's direction-dependent line rule, queued for the tiles of
// `framebuffer`; with the line stipple, cut by `stippler` (the pipeline's, whose counter
// outlives the batch).
void drawPointsAndLines(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                        LineStippler& stippler, const Framebuffer& framebuffer, PrimitiveQueue& queue);

// GL_SELECT: the window depths of the points and clipped segments that reach the view volume;
// GL_FEEDBACK (`feedback` not null): those points and segments themselves.
void selectPointsAndLines(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                          int framebufferHeight, HitRange& hits, FeedbackOutput* feedback);

}  // namespace glrenderer
