#include "points_lines.h"

#include "clip.h"
#include "clip_line.h"
#include "raster_line.h"
#include "raster_point.h"
#include "window_vertex.h"

namespace glrenderer {
namespace {

void drawSegment(const Vertex& start, const Vertex& end, const ViewportTransform& viewport, const DrawState& state,
                 const FragmentChoice& fragments, Framebuffer& framebuffer, Stats& stats) {
    Vertex a = start, b = end;
    const std::uint8_t outcodeA = clipOutcode(a.position), outcodeB = clipOutcode(b.position);
    if (!clipLine(a, b, outcodeA, outcodeB)) return;
    // An end that was outside has been moved by the clipper, which maps it unfused.
    const auto toWindow = [&](const Vertex& v, std::uint8_t outcode) {
        return outcode == 0 ? viewport.apply(v) : viewport.applyToClipped(v);
    };
    // Flat lines take the second vertex's color even when that end was clipped.
    rasterizeLine(toWindow(a, outcodeA), toWindow(b, outcodeB), end.color, state.lineWidth, fragments, framebuffer,
                  stats);
}

}  // namespace

void drawPointsAndLines(PrimitiveMode mode, std::span<const Vertex> vertices, const DrawState& state,
                        Framebuffer& framebuffer, Stats& stats) {
    const ViewportTransform viewport(state, framebuffer.height());
    const std::size_t n = vertices.size();
    if (mode == PrimitiveMode::Points) {
        const FragmentChoice fragments(bestFragmentPaths(), flatFragmentKey(state));
        for (const Vertex& v : vertices) {
            if (clipOutcode(v.position) == 0) rasterizePoint(viewport.apply(v), state, fragments, framebuffer, stats);
        }
        return;
    }
    const FragmentChoice fragments(bestFragmentPaths(), fragmentKey(state));
    switch (mode) {
    case PrimitiveMode::Lines:
        for (std::size_t i = 0; i + 1 < n; i += 2) {
            drawSegment(vertices[i], vertices[i + 1], viewport, state, fragments, framebuffer, stats);
        }
        break;
    case PrimitiveMode::LineStrip:
    case PrimitiveMode::LineLoop:
        for (std::size_t i = 0; i + 1 < n; ++i) {
            drawSegment(vertices[i], vertices[i + 1], viewport, state, fragments, framebuffer, stats);
        }
        if (mode == PrimitiveMode::LineLoop && n >= 2) {
            drawSegment(vertices[n - 1], vertices[0], viewport, state, fragments, framebuffer, stats);
        }
        break;
    default:
        break;
    }
}

}  // namespace glrenderer
