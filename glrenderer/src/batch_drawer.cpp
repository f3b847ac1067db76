#include "batch_drawer.h"

#include <cmath>

#include "clip.h"
#include "decompose.h"
#include "points_lines.h"
#include "raster_triangle.h"
#include "seed_culling.h"
#include "unfilled.h"

namespace glrenderer {
namespace {

// Window coordinates beyond this are only reachable through degenerate w; such triangles are
// dropped rather than fed to the fixed-point conversion.
constexpr float kMaxWindowCoordinate = 1 << 24;

bool isUsable(const WindowVertex& v) {
    return std::fabs(v.x) < kMaxWindowCoordinate && std::fabs(v.y) < kMaxWindowCoordinate &&
           std::isfinite(v.z) && std::isfinite(v.invW) && std::isfinite(v.color.r) &&
           std::isfinite(v.color.g) && std::isfinite(v.color.b) && std::isfinite(v.color.a);
}

bool isCulled(const DrawState& state, Facing facing) {
    if (!state.cullEnabled) return false;
    switch (state.cullFace) {
    case Face::Front: return facing == Facing::Front;
    case Face::Back: return facing == Facing::Back;
    case Face::FrontAndBack: return true;
    }
    return false;
}

}  // namespace

BatchDrawer::BatchDrawer(Framebuffer& framebuffer) : framebuffer_(framebuffer), tiles_(framebuffer) {}

void BatchDrawer::flush() { tiles_.flush(stats_, paintersSort_); }

void BatchDrawer::draw(const Batch& submitted) {
    // Without a color per vertex the reference's color is a constant of the draw, not an
    // interpolation of equal values (which perspective would blur by one unit here and there).
    Batch batch = submitted;
    if (!batch.colorsPerVertex) batch.state.shadeModel = ShadeModel::Flat;
    batch_ = &batch;
    paintersSort_ = batch.methods.hiddenSurface == HiddenSurface::PaintersSort;
    if (isTriangleMode(batch.mode)) {
        drawTriangles();
    } else {
        flush();  // points and lines are drawn at once: queued triangles first
        drawPointsAndLines(batch.mode, batch.vertices, batch.state, framebuffer_, stats_);
    }
    batch_ = nullptr;
}

void BatchDrawer::drawTriangles() {
    const Batch& batch = *batch_;
    const DrawState& state = batch.state;
    const ViewportTransform viewport(state, framebuffer_.height());
    const std::size_t count = batch.vertices.size();
    outcodes_.resize(count);
    windowVertices_.resize(count);
    std::uint8_t anyOutside = 0;
    for (std::size_t i = 0; i < count; ++i) {
        outcodes_[i] = clipOutcode(batch.vertices[i].position);
        anyOutside |= outcodes_[i];
        windowVertices_[i] = viewport.apply(batch.vertices[i]);
    }
    const bool filled = state.polygonFront == PolygonMode::Fill && state.polygonBack == PolygonMode::Fill;
    if (!filled) {
        const UnfilledTarget target{
            [&](const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                const glm::vec4& flatColor) { setupTriangle(v0, v1, v2, flatColor); },
            [&] { flush(); }};
        drawUnfilledBatch(batch.mode, batch.vertices, outcodes_, windowVertices_, viewport, state, framebuffer_,
                          stats_, target);
        return;
    }
    const DecompositionPath path = anyOutside == 0 ? DecompositionPath::Direct : DecompositionPath::DrawModule;
    const bool flatColorsPerVertex = state.shadeModel == ShadeModel::Flat && batch.colorsPerVertex;
    decomposeTriangles(batch.mode, static_cast<std::uint32_t>(count), path, flatColorsPerVertex,
                       [&](const TriangleIndices& t) { drawTriangle(t, viewport); });
}

void BatchDrawer::drawTriangle(const TriangleIndices& t, const ViewportTransform& viewport) {
    const Batch& batch = *batch_;
    const auto& vertices = batch.vertices;
    ++stats_.triangles;
    const glm::vec4& flatColor = vertices[t.v[2]].color;
    if (batch.methods.culling != CullMethod::WindowArea && batch.state.cullEnabled) {
        const Facing facing = seedFacing(batch.methods.culling, vertices[t.v[0]], vertices[t.v[1]],
                                         vertices[t.v[2]], batch.state.frontFaceCCW);
        if (facing != Facing::ZeroArea && isCulled(batch.state, facing)) {  // edge-on: the seeds keep it
            ++(facing == Facing::Front ? stats_.culledFront : stats_.culledBack);
            return;
        }
    }
    const std::uint8_t outsideAny = outcodes_[t.v[0]] | outcodes_[t.v[1]] | outcodes_[t.v[2]];
    if (outsideAny == 0) {
        setupTriangle(windowVertices_[t.v[0]], windowVertices_[t.v[1]], windowVertices_[t.v[2]], flatColor);
        return;
    }
    if (outcodes_[t.v[0]] & outcodes_[t.v[1]] & outcodes_[t.v[2]]) {
        ++stats_.clippedAway;
        return;
    }
    const ClippedPolygon polygon = clipTriangle(vertices[t.v[0]], vertices[t.v[1]], vertices[t.v[2]], outsideAny);
    if (polygon.count < 3) {
        ++stats_.clippedAway;
        return;
    }
    stats_.clipCreated += static_cast<std::uint64_t>(polygon.count - 3);
    // Input vertices keep the window position of the vertex stage; new ones get the clipper's.
    const auto window = [&](int i) {
        const int source = polygon.source[static_cast<std::size_t>(i)];
        return source == kNewVertex ? viewport.applyToClipped(polygon.vertices[static_cast<std::size_t>(i)])
                                    : windowVertices_[t.v[source]];
    };
    const WindowVertex first = window(0);
    WindowVertex previous = window(1);
    for (int i = 2; i < polygon.count; ++i) {
        const WindowVertex current = window(i);
        setupTriangle(previous, current, first, flatColor);
        previous = current;
    }
}

// Snaps, culls by the fixed-point area and queues one triangle in window coordinates.
void BatchDrawer::setupTriangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                                const glm::vec4& flatColor) {
    const DrawState& state = batch_->state;
    const Methods& methods = batch_->methods;
    if (!isUsable(v0) || !isUsable(v1) || !isUsable(v2)) {
        ++stats_.clippedAway;
        return;
    }
    SetupTriangle triangle{{v0, v1, v2}, {snap(v0), snap(v1), snap(v2)}, 0, flatColor};
    triangle.area = fixedArea(triangle.fixed[0], triangle.fixed[1], triangle.fixed[2]);
    const Facing facing = facingOf(triangle.area, state.frontFaceCCW);
    if (facing == Facing::ZeroArea) {
        ++stats_.culledZeroArea;
        return;
    }
    // The seeds' culling methods have decided already, before clipping.
    if (methods.culling == CullMethod::WindowArea && isCulled(state, facing)) {
        ++(facing == Facing::Front ? stats_.culledFront : stats_.culledBack);
        return;
    }
    ++stats_.rasterized;
    tiles_.add([&](RasterTriangle& prepared) {
        return prepareTriangle(triangle, state, methods, framebuffer_.width(), framebuffer_.height(), prepared);
    });
}

}  // namespace glrenderer
