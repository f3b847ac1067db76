#include "glrenderer/pipeline.h"

#include <cmath>

#include "clip.h"
#include "decompose.h"
#include "points_lines.h"
#include "raster_triangle.h"
#include "seed_culling.h"
#include "tile_rasterizer.h"
#include "unfilled.h"
#include "window_vertex.h"

namespace glrenderer {
namespace {

// Modes whose consecutive glBegin/glEnd blocks the reference merges into one draw.
bool isMergeable(PrimitiveMode mode) {
    return mode == PrimitiveMode::Points || mode == PrimitiveMode::Lines ||
           mode == PrimitiveMode::Triangles || mode == PrimitiveMode::Quads;
}

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

// Snaps, culls by the fixed-point area and queues one triangle in window coordinates.
void Pipeline::setupTriangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                             const glm::vec4& flatColor) {
    const DrawState& state = batchState_;
    Stats& stats = stats_;
    if (!isUsable(v0) || !isUsable(v1) || !isUsable(v2)) {
        ++stats.clippedAway;
        return;
    }
    SetupTriangle triangle{{v0, v1, v2}, {snap(v0), snap(v1), snap(v2)}, 0, flatColor};
    triangle.area = fixedArea(triangle.fixed[0], triangle.fixed[1], triangle.fixed[2]);
    const Facing facing = facingOf(triangle.area, state.frontFaceCCW);
    if (facing == Facing::ZeroArea) {
        ++stats.culledZeroArea;
        return;
    }
    // The seeds' culling methods have decided already, before clipping.
    if (methods_.culling == CullMethod::WindowArea && isCulled(state, facing)) {
        ++(facing == Facing::Front ? stats.culledFront : stats.culledBack);
        return;
    }
    ++stats.rasterized;
    RasterTriangle prepared;
    if (prepareTriangle(triangle, state, methods_, framebuffer_.width(), framebuffer_.height(), prepared)) {
        tiles_->add(prepared);
    }
}

void Pipeline::flushTiles() { tiles_->flush(stats_, methods_.hiddenSurface == HiddenSurface::PaintersSort); }

Pipeline::Pipeline(Framebuffer& framebuffer)
    : framebuffer_(framebuffer), tiles_(std::make_unique<TileRasterizer>(framebuffer)) {}
Pipeline::~Pipeline() = default;

void Pipeline::submit(const DrawState& state, PrimitiveMode mode, std::span<const Vertex> vertices) {
    stats_.vertices += vertices.size();
    ++stats_.primitivesByMode[static_cast<std::size_t>(mode)];
    const std::size_t usable = usableVertexCount(mode, vertices.size());
    if (usable == 0) return;
    if (!batch_.empty() && (mode != batchMode_ || !isMergeable(mode) || !(state == batchState_))) {
        endBatch();
    }
    batchState_ = state;
    batchMode_ = mode;
    batch_.insert(batch_.end(), vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(usable));
    if (!isMergeable(mode)) endBatch();
}

void Pipeline::endBatch() {
    if (batch_.empty()) return;
    drawBatch();
    batch_.clear();
}

void Pipeline::finish() {
    endBatch();
    flushTiles();
}

void Pipeline::clear(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24) {
    finish();
    if (color) framebuffer_.clearColor(rgba);
    if (depth) framebuffer_.clearDepth(depth24);
}

void Pipeline::drawBatch() {
    if (!isTriangleMode(batchMode_)) {
        flushTiles();  // points and lines are drawn at once: queued triangles first
        drawPointsAndLines(batchMode_, batch_, batchState_, framebuffer_, stats_);
        return;
    }
    const DrawState& state = batchState_;
    const ViewportTransform viewport(state, framebuffer_.height());

    outcodes_.resize(batch_.size());
    windowVertices_.resize(batch_.size());
    std::uint8_t anyOutside = 0;
    for (std::size_t i = 0; i < batch_.size(); ++i) {
        outcodes_[i] = clipOutcode(batch_[i].position);
        anyOutside |= outcodes_[i];
        windowVertices_[i] = viewport.apply(batch_[i]);
    }
    const bool filled = state.polygonFront == PolygonMode::Fill && state.polygonBack == PolygonMode::Fill;
    const DecompositionPath path =
        anyOutside == 0 && filled ? DecompositionPath::Direct : DecompositionPath::DrawModule;
    if (!filled) {
        const UnfilledTarget target{
            [&](const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                const glm::vec4& flatColor) { setupTriangle(v0, v1, v2, flatColor); },
            [&] { flushTiles(); }};
        drawUnfilledBatch(batchMode_, batch_, outcodes_, windowVertices_, viewport, state, framebuffer_,
                          stats_, target);
        return;
    }

    decomposeTriangles(batchMode_, static_cast<std::uint32_t>(batch_.size()), path, state.shadeModel,
                       [&](const TriangleIndices& t) { drawTriangle(t, viewport); });
}

void Pipeline::drawTriangle(const TriangleIndices& t, const ViewportTransform& viewport) {
    ++stats_.triangles;
    const glm::vec4& flatColor = batch_[t.v[2]].color;
    if (methods_.culling != CullMethod::WindowArea && batchState_.cullEnabled) {
        const Facing facing = seedFacing(methods_.culling, batch_[t.v[0]], batch_[t.v[1]], batch_[t.v[2]],
                                         batchState_.frontFaceCCW);
        if (facing != Facing::ZeroArea && isCulled(batchState_, facing)) {  // edge-on: the seeds keep it
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
    const ClippedPolygon polygon = clipTriangle(batch_[t.v[0]], batch_[t.v[1]], batch_[t.v[2]], outsideAny);
    if (polygon.count < 3) {
        ++stats_.clippedAway;
        return;
    }
    stats_.clipCreated += static_cast<std::uint64_t>(polygon.count - 3);
    const WindowVertex first = viewport.applyToClipped(polygon.vertices[0]);
    WindowVertex previous = viewport.applyToClipped(polygon.vertices[1]);
    for (int i = 2; i < polygon.count; ++i) {
        const WindowVertex current = viewport.applyToClipped(polygon.vertices[static_cast<std::size_t>(i)]);
        setupTriangle(previous, current, first, flatColor);
        previous = current;
    }
}

}  // namespace glrenderer
