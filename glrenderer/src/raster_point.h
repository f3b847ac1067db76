#pragma once
#include "fragment_paths.h"
#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/stats.h"
#include "window_vertex.h"

namespace glrenderer {

// Rasterizes a point (window coordinates, internal y-down, center inside the view volume) by
// the reference's legacy GL rule: a square of the integer-rounded size placed from the
// position snapped to 1/256 pixel, one constant color and depth. A non-finite or huge
// position draws nothing. The fragments take the path of `fragments`, a choice for
// flatFragmentKey(state).
void rasterizePoint(const WindowVertex& point, const DrawState& state, const FragmentChoice& fragments,
                    Framebuffer& framebuffer, Stats& stats);

}  // namespace glrenderer
