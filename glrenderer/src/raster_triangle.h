#pragma once
#include <cstdint>

#include <glm/vec4.hpp>

#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/methods.h"
#include "fragment_inputs.h"
#include "fragment_paths.h"
#include "pixel_rect.h"
#include "triangle_setup.h"

namespace glrenderer {

// A triangle ready for snapping and rasterization: window vertices in the reference's order,
// their snapped positions and the nonzero fixed-point area. flatColor is used under flat shading.
// (The vertices and the colour by address: setup reads them where the vertex stage left them.)
struct SetupTriangle {
    const WindowVertex* v[3];
    FixedPoint fixed[3];
    std::int64_t area;
    const glm::vec4* flatColor;
};

// E(p) = (b - a) x (p - a) for a triangle oriented so that its interior is E > 0, at pixel
// centers (whole numbers in fixed point). A center exactly on the edge belongs to the triangle
// only if the edge is a left edge, or a horizontal edge at the bottom in GL's y-up window
// (interior above): the reference's fill rule, folded into a bias so inside <=> E + bias >= 0.
struct EdgeFunction {
    std::int64_t stepX = 0, stepY = 0, valueAtOrigin = 0;  // per pixel, and at pixel (0, 0)

    EdgeFunction() = default;
    EdgeFunction(const FixedPoint& a, const FixedPoint& b);
    std::int64_t at(std::int64_t px, std::int64_t py) const { return valueAtOrigin + stepX * px + stepY * py; }
};

// Everything the kernel needs, computed once per triangle so that any tile can draw its part.
// What every triangle uses comes first: a mesh triangle's setup writes, and its tile reads, only
// the first three cache lines, kCommonTriangleBytes (FragmentInputs keeps its common fields first
// likewise; a fifth line written per triangle cost the torus 3% of its CPU time).
struct alignas(64) RasterTriangle {
    EdgeFunction edges[3];
    int minX = 0, maxX = -1, minY = 0, maxY = -1;  // inclusive pixel bounds, internal rows
    RasterMethod method = RasterMethod::Exact;
    // The painter's sort's key: the mean depth is this / 3, divided there (the division was a
    // wait in every triangle's setup).
    float depthSum = 0;
    float meanDepth() const { return depthSum / 3.0f; }
    FragmentInputs fragment;
    float windowX[3] = {}, windowY[3] = {};  // unsnapped, for the float methods
};

// The fragment key of a draw's triangles: the state's, with the methods' departures (the
// painter's sort replaces the depth test, screen-linear interpolation divides by no 1 / w).
FragmentKey triangleFragmentKey(const DrawState& state, const Methods& methods);

// Builds the edge functions and the planes the key of `fragments` reads, with pixel bounds
// clipped to `drawable` (drawableRect), and picks the triangle's fragment path from `fragments`. Returns
// false when no pixel center can be covered.
bool prepareTriangle(const SetupTriangle& triangle, const FragmentChoice& fragments, RasterMethod method,
                     const PixelRect& drawable, RasterTriangle& out);

// The exact method over the part of the triangle inside `rect`, tested pixel by pixel: integer
// edge functions at 1/256 pixel; the covered pixels go through the scalar fragment routine.
void rasterizeTriangleExact(const RasterTriangle& triangle, const PixelRect& rect, Framebuffer& framebuffer,
                            FragmentCounts& counts);

}  // namespace glrenderer
