#include "points_lines.h"

#include "clip.h"
#include "clip_line.h"
#include "feedback_output.h"
#include "raster_line.h"
#include "raster_point.h"
#include "smooth_primitives.h"
#include "window_vertex.h"

namespace glrenderer {
namespace {

// Visits the primitives of a points or lines batch as the reference draws them: each point
// inside the view volume, point(window vertex); each segment clipped, segment(window a, window b,
// the colour of its second vertex, which flat lines take even when that end was clipped, whether
// the line stipple restarts: each of GL_LINES, the first of a strip or loop).
template <class Point, class Segment>
void forEachPrimitive(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                      const ViewportTransform& viewport, Point&& point, Segment&& segment) {
    const UserClipPlanes& user = state.clipPlanes;
    const auto clipped = [&](const ClipVertex& start, const ClipVertex& end, bool restart) {
        ClipVertex a = start, b = end;
        const Outcode outcodeA = clipOutcode(a.position, user), outcodeB = clipOutcode(b.position, user);
        if (!clipLine(a, b, outcodeA, outcodeB, user)) return;
        // An end that was outside has been moved by the clipper, which maps it unfused.
        const auto toWindow = [&](const ClipVertex& v, Outcode outcode) {
            return outcode == 0 ? viewport.apply(v) : viewport.applyToClipped(v);
        };
        WindowVertex from = toWindow(a, outcodeA), to = toWindow(b, outcodeB);
        if (state.secondaryColors && state.shadeModel == ShadeModel::Flat) {
            from.secondaryColor = to.secondaryColor = end.secondaryColor;  // flat: both ends carry it
        }
        segment(from, to, end.color, restart);
    };
    const std::size_t n = vertices.size();
    switch (mode) {
    case PrimitiveMode::Points:
        for (const ClipVertex& v : vertices) {
            if (clipOutcode(v.position, user) == 0) point(viewport.apply(v));
        }
        break;
    case PrimitiveMode::Lines:
        for (std::size_t i = 0; i + 1 < n; i += 2) clipped(vertices[i], vertices[i + 1], true);
        break;
    case PrimitiveMode::LineStrip:
    case PrimitiveMode::LineLoop:
        for (std::size_t i = 0; i + 1 < n; ++i) clipped(vertices[i], vertices[i + 1], i == 0);
        if (mode == PrimitiveMode::LineLoop && n >= 2) clipped(vertices[n - 1], vertices[0], false);
        break;
    default: break;
    }
}

}  // namespace

void drawPointsAndLines(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                        LineStippler& stippler, const Framebuffer& framebuffer, PrimitiveQueue& queue) {
    // Points are drawn flat; lines as the state says; smooth ones as smoothFragmentKey says.
    const bool smooth = mode == PrimitiveMode::Points ? state.pointSmooth : state.lineSmooth;
    const FragmentKey key = smooth                          ? smoothFragmentKey(state)
                            : mode == PrimitiveMode::Points ? flatFragmentKey(state)
                                                            : fragmentKey(state);
    const FragmentChoice fragments(bestFragmentPaths(), key, state);
    const PixelRect drawable = drawableRect(state.fragmentOps.scissor, framebuffer.width(), framebuffer.height());
    forEachPrimitive(
        mode, vertices, state, ViewportTransform(state, framebuffer.height()),
        [&](const WindowVertex& v) {
            if (smooth) return queueSmoothPoint(v, state, fragments, drawable, queue);
            queuePoint(v, state, fragments, drawable, queue);
        },
        [&](const WindowVertex& a, const WindowVertex& b, const glm::vec4& flatColor, bool restart) {
            const auto draw = [&](const WindowVertex& from, const WindowVertex& to) {
                if (smooth) return queueSmoothLine(from, to, flatColor, state, fragments, drawable, queue);
                queueLine(from, to, flatColor, state.lineWidth, fragments, drawable, queue);
            };
            if (!state.lineStipple.enabled) return draw(a, b);
            if (restart) stippler.restart();
            stippler.cut(state.lineStipple, a, b, smooth, draw);
        });
}

void selectPointsAndLines(PrimitiveMode mode, std::span<const ClipVertex> vertices, const DrawState& state,
                          int framebufferHeight, HitRange& hits, FeedbackOutput* feedback) {
    const ViewportTransform viewport(state, framebufferHeight);
    if (feedback) {
        forEachPrimitive(
            mode, vertices, state, viewport, [&](const WindowVertex& v) { feedback->point(v); },
            [&](const WindowVertex& a, const WindowVertex& b, const glm::vec4&, bool) { feedback->line(a, b); });
        return;
    }
    forEachPrimitive(
        mode, vertices, state, viewport, [&](const WindowVertex& v) { hits.add(v.z); },
        [&](const WindowVertex& a, const WindowVertex& b, const glm::vec4&, bool) { hits.add(a.z), hits.add(b.z); });
}

}  // namespace glrenderer
