#include "points_lines.h"

#include "clip.h"
#include "clip_line.h"
#include "feedback_output.h"
#include "raster_line.h"
#include "raster_point.h"
#include "window_vertex.h"

namespace glrenderer {
namespace {

// Visits the primitives of a points or lines batch as the reference draws them: each point
// inside the view volume, point(window vertex); each segment clipped, segment(window a, window b,
// the colour of its second vertex, which flat lines take even when that end was clipped).
template <class Point, class Segment>
void forEachPrimitive(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                      const ViewportTransform& viewport, Point&& point, Segment&& segment) {
    const UserClipPlanes& user = state.clipPlanes;
    const auto clipped = [&](const ClipVertex& start, const ClipVertex& end) {
        ClipVertex a = start, b = end;
        const Outcode outcodeA = clipOutcode(a.position, user), outcodeB = clipOutcode(b.position, user);
        if (!clipLine(a, b, outcodeA, outcodeB, user)) return;
        // An end that was outside has been moved by the clipper, which maps it unfused.
        const auto toWindow = [&](const ClipVertex& v, Outcode outcode) {
            return outcode == 0 ? viewport.apply(v) : viewport.applyToClipped(v);
        };
        segment(toWindow(a, outcodeA), toWindow(b, outcodeB), end.color);
    };
    const std::size_t n = vertices.size();
    switch (mode) {
    case PrimitiveMode::Points:
        for (const ClipVertex& v : vertices) {
            if (clipOutcode(v.position, user) == 0) point(viewport.apply(v));
        }
        break;
    case PrimitiveMode::Lines:
        for (std::size_t i = 0; i + 1 < n; i += 2) clipped(vertices[i], vertices[i + 1]);
        break;
    case PrimitiveMode::LineStrip:
    case PrimitiveMode::LineLoop:
        for (std::size_t i = 0; i + 1 < n; ++i) clipped(vertices[i], vertices[i + 1]);
        if (mode == PrimitiveMode::LineLoop && n >= 2) clipped(vertices[n - 1], vertices[0]);
        break;
    default:
        break;
    }
}

}  // namespace

void drawPointsAndLines(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                        Framebuffer& framebuffer, Stats& stats) {
    // Points are drawn flat; lines as the state says.
    const FragmentChoice fragments(bestFragmentPaths(),
                                   mode == PrimitiveMode::Points ? flatFragmentKey(state) : fragmentKey(state), state);
    forEachPrimitive(
        mode, vertices, state, ViewportTransform(state, framebuffer.height()),
        [&](const WindowVertex& v) { rasterizePoint(v, state, fragments, framebuffer, stats); },
        [&](const WindowVertex& a, const WindowVertex& b, const glm::vec4& flatColor) {
            rasterizeLine(a, b, flatColor, state.lineWidth, fragments, framebuffer, stats);
        });
}

void selectPointsAndLines(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                          int framebufferHeight, HitRange& hits, FeedbackOutput* feedback) {
    const ViewportTransform viewport(state, framebufferHeight);
    if (feedback) {
        forEachPrimitive(
            mode, vertices, state, viewport, [&](const WindowVertex& v) { feedback->point(v); },
            [&](const WindowVertex& a, const WindowVertex& b, const glm::vec4&) { feedback->line(a, b); });
        return;
    }
    forEachPrimitive(
        mode, vertices, state, viewport, [&](const WindowVertex& v) { hits.add(v.z); },
        [&](const WindowVertex& a, const WindowVertex& b, const glm::vec4&) { hits.add(a.z), hits.add(b.z); });
}

}  // namespace glrenderer
