#pragma once
#include <glm/vec4.hpp>

#include "fragment_paths.h"
#include "pixel_rect.h"
#include "tiled_primitive.h"
#include "window_vertex.h"

namespace glrenderer {

// Queues for the tiles the segment from `start` to `end` (window coordinates, internal y-down, already
// inside the view volume) as the reference's non-antialiased lines: a parallelogram of the
// integer-rounded width whose ends are moved by the diamond-exit test, so that the pixels lit
// depend on the direction of the segment. Smooth colors are interpolated along the major axis
// from the unsnapped ends; flat lines take `flatColor` (the second vertex's, provoking last).
// The fragments take the path of `fragments` (a choice for fragmentKey(state)), in `drawable`.
// Segments with a non-finite or huge end draw nothing.
void queueLine(const WindowVertex& start, const WindowVertex& end, const glm::vec4& flatColor, float lineWidth,
               const FragmentChoice& fragments, const PixelRect& drawable, PrimitiveQueue& queue);

}  // namespace glrenderer
