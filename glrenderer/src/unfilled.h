#pragma once
#include <cstdint>
#include <functional>
#include <span>

#include <glm/vec4.hpp>

#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/stats.h"
#include "clip.h"
#include "clip_vertex.h"
#include "feedback_output.h"
#include "line_stipple.h"
#include "tiled_primitive.h"
#include "window_vertex.h"

namespace glrenderer {

// Where the unfilled stage sends what it does not draw itself.
struct UnfilledTarget {
    // A triangle of a face whose polygon mode is FILL, already clipped, to snap, cull and fill.
    std::function<void(const WindowVertex&, const WindowVertex&, const WindowVertex&, const glm::vec4&)> fill;
    // Where lines and points are queued, after the filled triangles before them (drawing only).
    PrimitiveQueue* queue = nullptr;
    // GL_FEEDBACK: lines and points go there instead of being drawn.
    FeedbackOutput* feedback = nullptr;
    // Cuts the lines under the line stipple (the pipeline's; drawing only).
    LineStippler* stippler = nullptr;
};

// Draws a batch of a triangle mode under glPolygonMode LINE/POINT for at least one face, as the
// reference's draw module does: triangles decomposed with edge flags that hide the interior
// edges of quads, quad strips and polygons; clipped (frontier edges hidden); culled by a float
// determinant of window coordinates (zero area is back-facing); then each face drawn in its
// mode, edges as lines (v2->v0, v0->v1, v1->v2) or vertices as points where the edge flag of
// the primitive and of the edge's first vertex (glEdgeFlag) are both set. Flat shading uses the
// triangle's provoking vertex color for all of it. `anyEdgeShown` false: the vertices carry no
// edge flags of their own and the current one is false, so every edge is hidden; the reference
// then culls the faces drawn as lines or points (even the edges clip planes make).
void drawUnfilledBatch(PrimitiveMode mode, std::span<const ClipVertex> vertices, std::span<const Outcode> outcodes,
                       std::span<const WindowVertex> windowVertices, const ViewportTransform& viewport,
                       const DrawState& state, bool anyEdgeShown, Framebuffer& framebuffer, Stats& stats,
                       const UnfilledTarget& target);

}  // namespace glrenderer
