#pragma once
#include "fragment_paths.h"
#include "glrenderer/draw_state.h"
#include "pixel_rect.h"
#include "tiled_primitive.h"
#include "window_vertex.h"

namespace glrenderer {

// Queues for the tiles a point (window coordinates, internal y-down, center inside the view volume) by
// the reference's legacy GL rule: a square of the integer-rounded size placed from the
// position snapped to 1/256 pixel, one constant color and depth. A non-finite or huge
// position draws nothing. The fragments take the path of `fragments`, a choice for
// flatFragmentKey(state), in `drawable`.
void queuePoint(const WindowVertex& point, const DrawState& state, const FragmentChoice& fragments,
                const PixelRect& drawable, PrimitiveQueue& queue);

}  // namespace glrenderer
