#include "unfilled.h"

#include <array>
#include <cmath>

#include "clip.h"
#include "polygon_offset.h"
#include "raster_line.h"
#include "raster_point.h"
#include "smooth_primitives.h"
#include "triangle_setup.h"

namespace glrenderer {
namespace {

// Which edges of a decomposed triangle are polygon edges: bit k is the edge v[k] -> v[k+1].
constexpr std::uint8_t kEdge0 = 1, kEdge1 = 2, kEdge2 = 4, kAllEdges = 7;
// The triangle starts a primitive of its own (each triangle of a list, strip or fan, the first
// of a quad or polygon): the line stipple restarts at its edges (GL_LINE_RESET_TOKEN in feedback).
constexpr std::uint8_t kResetStipple = 8;

// The draw module's decomposition (provoking vertex last) with edge flags.
template <class Emit>
void decomposeWithEdges(PrimitiveMode mode, std::uint32_t n, Emit&& emit) {
    switch (mode) {
    case PrimitiveMode::Triangles:
        for (std::uint32_t i = 0; i + 2 < n; i += 3) emit(i, i + 1, i + 2, kAllEdges | kResetStipple);
        break;
    case PrimitiveMode::TriangleStrip:
        for (std::uint32_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0)
                emit(i, i + 1, i + 2, kAllEdges | kResetStipple);
            else
                emit(i + 1, i, i + 2, kAllEdges | kResetStipple);
        }
        break;
    case PrimitiveMode::TriangleFan:
        for (std::uint32_t i = 1; i + 1 < n; ++i) emit(0, i, i + 1, kAllEdges | kResetStipple);
        break;
    case PrimitiveMode::Quads:
        for (std::uint32_t i = 0; i + 3 < n; i += 4) {
            emit(i, i + 1, i + 3, kEdge0 | kEdge2 | kResetStipple);
            emit(i + 1, i + 2, i + 3, kEdge0 | kEdge1);
        }
        break;
    case PrimitiveMode::QuadStrip:
        for (std::uint32_t i = 0; i + 3 < n; i += 2) {
            emit(i + 2, i, i + 3, kEdge0 | kEdge2 | kResetStipple);
            emit(i, i + 1, i + 3, kEdge0 | kEdge1);
        }
        break;
    case PrimitiveMode::Polygon:
        // Fan (i+1, i+2, 0): the outer edge i+1 -> i+2, plus 0 -> 1 first and n-1 -> 0 last.
        for (std::uint32_t i = 0; i + 2 < n; ++i) {
            std::uint8_t edges = kEdge0;
            if (i == 0) edges |= kEdge2 | kResetStipple;
            if (i + 3 == n) edges |= kEdge1;
            emit(i + 1, i + 2, 0, edges);
        }
        break;
    default: break;
    }
}

// A vertex of a (possibly clipped) polygon: clip and window position, its own edge flag, and
// whether the polygon edge starting at it is drawn.
struct PolygonVertex {
    ClipVertex clip;
    WindowVertex window;
    bool edgeFlag;
    bool edgeVisible;
};

struct Polygon {
    std::array<PolygonVertex, kMaxClippedVertices> v;
    int count = 0;
};

// Sutherland-Hodgman in the reference's plane order, carrying edge flags: an edge cut by a
// plane keeps its flag up to the cut; the new edge along the plane is hidden for the view
// volume's planes and drawn for the program's.
// Returns false if the polygon vanished or a distance is not finite.
bool clipPolygon(Polygon& polygon, Outcode outcodeUnion, const ViewportTransform& viewport,
                 const UserClipPlanes& user) {
    Polygon out;
    for (int plane = 0; plane < kClipPlaneCount; ++plane) {
        if (!(outcodeUnion & (1u << plane))) continue;
        out.count = 0;
        const int n = polygon.count;
        for (int i = 0; i < n; ++i) {
            const PolygonVertex& prev = polygon.v[static_cast<std::size_t>(i)];
            const PolygonVertex& next = polygon.v[static_cast<std::size_t>((i + 1) % n)];
            const float dPrev = clipPlaneDistance(prev.clip.position, plane, user);
            const float dNext = clipPlaneDistance(next.clip.position, plane, user);
            if (!std::isfinite(dPrev) || !std::isfinite(dNext)) return false;
            if (dPrev >= 0.0f) out.v[static_cast<std::size_t>(out.count++)] = prev;
            if ((dPrev >= 0.0f) == (dNext >= 0.0f)) continue;
            PolygonVertex cut;
            cut.clip = clipCrossing(prev.clip, dPrev, next.clip, dNext);
            cut.window = viewport.applyToClipped(cut.clip);
            // Leaving, the edge from the cut runs along the plane: hidden along the view
            // volume's planes, drawn along the program's (the reference copies NVIDIA there).
            const bool leaving = dNext < 0.0f;
            if (leaving && plane >= kViewVolumePlanes) {
                cut.edgeFlag = cut.edgeVisible = true;
            } else {
                cut.edgeFlag = leaving ? false : prev.edgeFlag;
                cut.edgeVisible = prev.edgeVisible;
            }
            out.v[static_cast<std::size_t>(out.count++)] = cut;
        }
        polygon = out;
        if (polygon.count < 3) return false;
    }
    return true;
}

// The key of an unfilled face's lines or points: polygon stipple masks them too when a filled
// face of the same draw reaches the reference's polygon stipple stage, which binds its stippled
// fragment shader for everything its draw module then sends to the rasterizer.
FragmentKey unfilledKey(FragmentKey key, const DrawState& state, bool stippled) {
    key.polygonStipple = stippled && state.polygonStipple.active();
    return key;
}

class UnfilledDrawer {
public:
    // `survey`: only find whether a face is filled (filledFace()), drawing nothing; `stippled`:
    // the lines and points take the polygon stipple.
    UnfilledDrawer(const DrawState& state, bool anyEdgeShown, Framebuffer& framebuffer, Stats& stats,
                   const UnfilledTarget& target, bool survey, bool stippled)
        : state_(state),
          anyEdgeShown_(anyEdgeShown),
          survey_(survey),
          drawable_(drawableRect(state.fragmentOps.scissor, framebuffer.width(), framebuffer.height())),
          stats_(stats),
          target_(target),
          lineFragments_(bestFragmentPaths(),
                         unfilledKey(state.lineSmooth ? smoothFragmentKey(state) : fragmentKey(state), state, stippled),
                         state),
          pointFragments_(
              bestFragmentPaths(),
              unfilledKey(state.pointSmooth ? smoothFragmentKey(state) : flatFragmentKey(state), state, stippled),
              state) {}

    bool filledFace() const { return filledFace_; }

    // One triangle out of the clipper (provoking vertex last) with its edge bits and the
    // provoking vertex (for its flat colours).
    void triangle(const PolygonVertex& a, const PolygonVertex& b, const PolygonVertex& c, std::uint8_t edges,
                  const ClipVertex& provoking) {
        WindowVertex w0 = a.window, w1 = b.window, w2 = c.window;
        const float det = drawModuleDeterminant(w0, w1, w2);
        const bool front = drawModuleFacing(det, state_.frontFaceCCW) == Facing::Front;
        // The draw module's two-sided stage: a triangle facing back by its determinant (not 0)
        // takes the back colours, whatever the mode draws.
        const bool back = state_.twoSidedColors && !front && det != 0.0f;
        if (back) w0.color = a.clip.backColor, w1.color = b.clip.backColor, w2.color = c.clip.backColor;
        const glm::vec4& flatColor = back ? provoking.backColor : provoking.color;
        // Secondary colours: under flat shading every vertex carries the provoking vertex's.
        if (state_.secondaryColors) {
            const auto secondary = [&](const ClipVertex& v) { return back ? v.backSecondaryColor : v.secondaryColor; };
            const bool flat = state_.shadeModel == ShadeModel::Flat;
            w0.secondaryColor = secondary(flat ? provoking : a.clip);
            w1.secondaryColor = secondary(flat ? provoking : b.clip);
            w2.secondaryColor = secondary(flat ? provoking : c.clip);
        }
        const bool culled =
            state_.cullEnabled && (state_.cullFace == Face::FrontAndBack || (state_.cullFace == Face::Front) == front);
        // With every edge hidden, the reference culls the faces drawn as lines or points.
        const bool hidden = !anyEdgeShown_ && (front ? state_.polygonFront : state_.polygonBack) != PolygonMode::Fill;
        if (culled || hidden) {
            ++(front ? stats_.culledFront : stats_.culledBack);
            return;
        }
        // The mode follows the facing. A zero determinant is back-facing when culling is on;
        // with culling off it counts as clockwise (measured: the back mode under GL_CCW, the
        // front mode under GL_CW).
        const bool useFront = det == 0.0f ? !state_.cullEnabled && !state_.frontFaceCCW : front;
        const PolygonMode mode = useFront ? state_.polygonFront : state_.polygonBack;
        if (survey_) {
            filledFace_ = filledFace_ || mode == PolygonMode::Fill;
            return;
        }
        const PolygonOffset& offset = offsetFor(mode);
        // The stipple stage restarts its counter at each face that reaches it, but for the
        // edges of one polygon drawn as lines.
        if (stippling_ && (mode != PolygonMode::Line || (edges & kResetStipple))) target_.stippler->restart();
        // Polygon offset in the draw module: on the vertices, filled faces' too.
        if (offsetStage_) offsetInDrawModule(offset, w0, w1, w2);
        if (mode == PolygonMode::Fill) {
            target_.fill(w0, w1, w2, flatColor);
            return;
        }
        ++stats_.rasterized;
        const bool flat = state_.shadeModel == ShadeModel::Flat;
        if (mode == PolygonMode::Line && (edges & kResetStipple) && target_.feedback)
            target_.feedback->resetLineStipple();
        if (mode == PolygonMode::Line) {
            if ((edges & kEdge2) && c.edgeFlag) line(w2, w0, flatColor);
            if ((edges & kEdge0) && a.edgeFlag) line(w0, w1, flatColor);
            if ((edges & kEdge1) && b.edgeFlag) line(w1, w2, flatColor);
        } else {
            if ((edges & kEdge0) && a.edgeFlag) point(w0, flat, flatColor);
            if ((edges & kEdge1) && b.edgeFlag) point(w1, flat, flatColor);
            if ((edges & kEdge2) && c.edgeFlag) point(w2, flat, flatColor);
        }
    }

private:
    // The draw module's offset stage, there when any offset mode is on, decides at the draw's
    // first triangle, by its mode, whether to offset, and then offsets every triangle of the draw
    // alike: by the state's offset, or by none (0 times a slope: NaN, so depth 0, where the
    // slope is not finite).
    const PolygonOffset& offsetFor(PolygonMode firstMode) {
        static constexpr PolygonOffset kNone{};
        if (!offsetChosen_) {
            offsetChosen_ = true;
            const PolygonOffset& o = state_.polygonOffset;
            offsetOn_ = firstMode == PolygonMode::Fill ? o.fill : firstMode == PolygonMode::Line ? o.line : o.point;
        }
        return offsetOn_ ? state_.polygonOffset : kNone;
    }

    void line(const WindowVertex& from, const WindowVertex& to, const glm::vec4& flatColor) {
        if (target_.feedback) return target_.feedback->line(flatColored(from, flatColor), flatColored(to, flatColor));
        const auto draw = [&](const WindowVertex& a, const WindowVertex& b) {
            if (state_.lineSmooth)
                return queueSmoothLine(a, b, flatColor, state_, lineFragments_, drawable_, *target_.queue);
            queueLine(a, b, flatColor, state_.lineWidth, lineFragments_, drawable_, *target_.queue);
        };
        if (stippling_) return target_.stippler->cut(state_.lineStipple, from, to, state_.lineSmooth, draw);
        draw(from, to);
    }
    void point(const WindowVertex& p, bool flat, const glm::vec4& flatColor) {
        if (target_.feedback) return target_.feedback->point(flatColored(p, flatColor));
        WindowVertex colored = p;
        if (flat) colored.color = flatColor;
        if (state_.pointSmooth) return queueSmoothPoint(colored, state_, pointFragments_, drawable_, *target_.queue);
        queuePoint(colored, state_, pointFragments_, drawable_, *target_.queue);
    }

    // Feedback's vertex: with flat shading the draw module's flatshade stage has given it the
    // provoking vertex's colour.
    WindowVertex flatColored(const WindowVertex& v, const glm::vec4& flatColor) const {
        WindowVertex out = v;
        if (state_.shadeModel == ShadeModel::Flat) out.color = flatColor;
        return out;
    }

    const DrawState& state_;
    const bool anyEdgeShown_;  // false: the batch's edges are all hidden by the current edge flag
    const bool survey_;
    bool filledFace_ = false;
    const bool offsetStage_ = state_.polygonOffset.fill || state_.polygonOffset.line || state_.polygonOffset.point;
    bool offsetChosen_ = false, offsetOn_ = false;
    const PixelRect drawable_;
    Stats& stats_;
    const UnfilledTarget& target_;
    const bool stippling_ = state_.lineStipple.enabled && target_.stippler;
    const FragmentChoice lineFragments_, pointFragments_;  // the batch's, chosen once
};

// Decomposes, clips and hands `drawer` a batch's faces.
void runUnfilled(UnfilledDrawer& drawer, PrimitiveMode mode, std::span<const ClipVertex> vertices,
                 std::span<const Outcode> outcodes, std::span<const WindowVertex> windowVertices,
                 const ViewportTransform& viewport, const DrawState& state, Stats& stats) {
    const auto count = static_cast<std::uint32_t>(vertices.size());
    decomposeWithEdges(mode, count, [&](std::uint32_t i0, std::uint32_t i1, std::uint32_t i2, std::uint8_t edges) {
        ++stats.triangles;
        const std::uint32_t index[3] = {i0, i1, i2};
        Polygon polygon;
        polygon.count = 3;
        for (std::size_t k = 0; k < 3; ++k) {
            const ClipVertex& v = vertices[index[k]];
            polygon.v[k] = {v, windowVertices[index[k]], v.edgeFlag, (edges >> k & 1u) != 0};
        }
        const Outcode outside = outcodes[i0] | outcodes[i1] | outcodes[i2];
        if (outside == 0) {
            drawer.triangle(polygon.v[0], polygon.v[1], polygon.v[2], edges, vertices[i2]);
            return;
        }
        if ((outcodes[i0] & outcodes[i1] & outcodes[i2]) ||
            !clipPolygon(polygon, outside, viewport, state.clipPlanes)) {
            ++stats.clippedAway;
            return;
        }
        stats.clipCreated += static_cast<std::uint64_t>(polygon.count - 3);
        // Fan (p[i-1], p[i], p[0]) with p[0] last; inner diagonals hidden.
        for (int i = 2; i < polygon.count; ++i) {
            const PolygonVertex& a = polygon.v[static_cast<std::size_t>(i - 1)];
            const PolygonVertex& b = polygon.v[static_cast<std::size_t>(i)];
            const PolygonVertex& first = polygon.v[0];
            std::uint8_t fanEdges = a.edgeVisible ? kEdge0 : 0;
            if (i == 2 && first.edgeVisible) fanEdges |= kEdge2;
            if (i == 2) fanEdges |= kResetStipple;  // the clipper's first triangle, whatever the original's
            if (i == polygon.count - 1 && b.edgeVisible) fanEdges |= kEdge1;
            drawer.triangle(a, b, first, fanEdges, vertices[i2]);
        }
    });
}

}  // namespace

void drawUnfilledBatch(PrimitiveMode mode, std::span<const ClipVertex> vertices, std::span<const Outcode> outcodes,
                       std::span<const WindowVertex> windowVertices, const ViewportTransform& viewport,
                       const DrawState& state, bool anyEdgeShown, Framebuffer& framebuffer, Stats& stats,
                       const UnfilledTarget& target) {
    // Under polygon stipple, a first pass finds whether any face is drawn filled.
    bool stippled = false;
    if (state.polygonStipple.active() && !target.feedback &&
        (state.polygonFront == PolygonMode::Fill || state.polygonBack == PolygonMode::Fill)) {
        Stats uncounted;
        UnfilledDrawer survey(state, anyEdgeShown, framebuffer, uncounted, target, true, false);
        runUnfilled(survey, mode, vertices, outcodes, windowVertices, viewport, state, uncounted);
        stippled = survey.filledFace();
    }
    UnfilledDrawer drawer(state, anyEdgeShown, framebuffer, stats, target, false, stippled);
    runUnfilled(drawer, mode, vertices, outcodes, windowVertices, viewport, state, stats);
}

}  // namespace glrenderer
