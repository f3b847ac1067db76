#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/stats.h"
#include "triangle_setup.h"

namespace glrenderer {

// A triangle ready for rasterization: window vertices in the reference's order, their snapped
// positions and the nonzero fixed-point area. flatColor is used under flat shading.
struct SetupTriangle {
    WindowVertex v[3];
    FixedPoint fixed[3];
    std::int64_t area;
    glm::vec4 flatColor;
};

// The exact method: integer edge functions at 1/256 pixel with the reference's fill rule,
// perspective-correct color, 24-bit depth. Counts fragments into stats.
void rasterizeTriangleExact(const SetupTriangle& triangle, const DrawState& state,
                            Framebuffer& framebuffer, Stats& stats);

}  // namespace glrenderer
