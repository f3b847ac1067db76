#include "points_lines.h"

#include "clip.h"
#include "clip_line.h"
#include "raster_line.h"
#include "raster_point.h"
#include "window_vertex.h"

namespace glrenderer {
namespace {

void drawSegment(const Vertex& start, const Vertex& end, const ViewportTransform& viewport,
                 const DrawState& state, Framebuffer& framebuffer, Stats& stats) {
    Vertex a = start, b = end;
    if (!clipLine(a, b, clipOutcode(a.position), clipOutcode(b.position))) return;
    // Flat lines take the second vertex's color even when that end was clipped.
    rasterizeLine(viewport.apply(a), viewport.apply(b), end.color, state, framebuffer, stats);
}

}  // namespace

void drawPointsAndLines(PrimitiveMode mode, std::span<const Vertex> vertices, const DrawState& state,
                        Framebuffer& framebuffer, Stats& stats) {
    const ViewportTransform viewport(state, framebuffer.height());
    const std::size_t n = vertices.size();
    switch (mode) {
    case PrimitiveMode::Points:
        for (const Vertex& v : vertices) {
            if (clipOutcode(v.position) == 0) rasterizePoint(viewport.apply(v), state, framebuffer, stats);
        }
        break;
    case PrimitiveMode::Lines:
        for (std::size_t i = 0; i + 1 < n; i += 2) {
            drawSegment(vertices[i], vertices[i + 1], viewport, state, framebuffer, stats);
        }
        break;
    case PrimitiveMode::LineStrip:
    case PrimitiveMode::LineLoop:
        for (std::size_t i = 0; i + 1 < n; ++i) {
            drawSegment(vertices[i], vertices[i + 1], viewport, state, framebuffer, stats);
        }
        if (mode == PrimitiveMode::LineLoop && n >= 2) {
            drawSegment(vertices[n - 1], vertices[0], viewport, state, framebuffer, stats);
        }
        break;
    default:
        break;
    }
}

}  // namespace glrenderer
