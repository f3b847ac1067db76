#pragma once
// Polygon offset as the reference computes it: one depth offset per triangle,
// factor * max(|dz/dx|, |dz/dy|) + units * r, r the 24-bit buffer's resolution. Filled
// triangles take it in llvmpipe's setup, and each fragment adds it to its interpolated z;
// unfilled ones take it in the draw module's offset stage, which adds it to the vertices' z
// (clamped to [0, 1]) before their edges or vertices are drawn. The two compute the slopes
// from different differences.
#include "glrenderer/polygon_offset.h"
#include "window_vertex.h"

namespace glrenderer {

// llvmpipe's setup (lp_do_offset_tri), for (v0, v1, v2) in the order setup builds its planes.
float setupDepthOffset(const PolygonOffset& offset, const WindowVertex& v0, const WindowVertex& v1,
                       const WindowVertex& v2);

// The draw module (draw_pipe_offset.c), for (v0, v1, v2) in the order the triangle reaches it.
void offsetInDrawModule(const PolygonOffset& offset, WindowVertex& v0, WindowVertex& v1, WindowVertex& v2);

}  // namespace glrenderer
