#pragma once
#include <glm/vec4.hpp>

#include "fragment_paths.h"
#include "glrenderer/draw_state.h"
#include "pixel_rect.h"
#include "tiled_primitive.h"
#include "window_vertex.h"

namespace glrenderer {

// The fragment key of a draw's smooth points and lines: flat (their colour reaches the stage
// per fragment, coverage in its alpha), GL_REPLACE as GL_MODULATE (drawSmoothTriangle).
FragmentKey smoothFragmentKey(const DrawState& state);

// GL_POINT_SMOOTH as the reference draws it (draw_pipe_aapoint.c): a square of radius
// max(size / 2, 1) around the point in two triangles, with a varying (s, t, k, 1), s and t
// from -1 to 1, k = (1 - 1 / radius)^2; a fragment with s^2 + t^2 = d > 1 is dropped, one with
// d <= k has its alpha times (1 - d) / (1 - k) (Mesa 22.3's NIR lowering selects the factor
// so, the reverse of its TGSI one), others keep it. `fragments`: a choice for smoothFragmentKey(state).
void queueSmoothPoint(const WindowVertex& point, const DrawState& state, const FragmentChoice& fragments,
                      const PixelRect& drawable, PrimitiveQueue& queue);

// GL_LINE_SMOOTH as the reference draws it (draw_pipe_aaline.c): the segment lengthened by
// 1/2 pixel at each end and widened to 2 * half-width (half-width 1 up to width 1, else
// width / 2 + 1/2) in two triangles, with a varying (across, half-width, along, half-length);
// each fragment's alpha times clamp(half-width - |across|) * clamp(half-length - |along|).
// Flat lines take `flatColor` at both ends. `fragments`: a choice for smoothFragmentKey(state).
void queueSmoothLine(const WindowVertex& start, const WindowVertex& end, const glm::vec4& flatColor,
                     const DrawState& state, const FragmentChoice& fragments, const PixelRect& drawable,
                     PrimitiveQueue& queue);

}  // namespace glrenderer
