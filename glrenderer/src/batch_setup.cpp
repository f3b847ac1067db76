#include "batch_setup.h"

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#include "clip.h"
#include "decompose.h"
#include "polygon_offset.h"
#include "seed_culling.h"
#include "vertex_stage.h"

namespace glrenderer {
namespace {

// The vertices of a segment in which the reference's draw module takes a long draw of quads.
constexpr std::uint32_t kQuadSegmentVertices = 4096;

bool areUsable(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2) {
    return _mm_movemask_ps(_mm_and_ps(_mm_and_ps(usableLanes(v0), usableLanes(v1)), usableLanes(v2))) == 0xF;
}

// Counts a triangle culled for its facing.
void countCulled(Stats& stats, Facing facing) { ++(facing == Facing::Front ? stats.culledFront : stats.culledBack); }

bool isCulled(const DrawState& state, Facing facing) {
    if (!state.cullEnabled) return false;
    switch (state.cullFace) {
    case Face::Front: return facing == Facing::Front;
    case Face::Back: return facing == Facing::Back;
    case Face::FrontAndBack: return true;
    }
    return false;
}

// Keeps triangles in the writer's slots and lists them, in order.
class ListingTarget final : public TriangleTarget {
public:
    ListingTarget(ArenaWriter& writer, std::vector<const RasterTriangle*>& list) : writer_(writer), list_(list) {}
    RasterTriangle& slot() override { return writer_.slot(); }
    void keep() override {
        writer_.keep();
        list_.push_back(&writer_.last());
    }

private:
    ArenaWriter& writer_;
    std::vector<const RasterTriangle*>& list_;
};

}  // namespace

bool BatchSetup::handles(const BatchHeader& batch) {
    // (Selection and feedback draw no triangles: BatchDrawer::select takes them, also when a
    // chunk is set up ahead on another thread.)
    return isTriangleMode(batch.mode) && !batch.state->selection && !batch.state->feedback && filled(*batch.state);
}

bool BatchSetup::setUp(BatchChunk& chunk, ArenaWriter& writer) {
    lightChunk(chunk);
    for (const BatchEntry& entry : chunk.batches) {
        if (!handles(entry)) return false;
    }
    ListingTarget listing(writer, chunk.setUpTriangles);
    for (const BatchEntry& entry : chunk.batches) setUp(chunk.batch(entry), listing, chunk.setupStats);
    chunk.setUp = true;
    return true;
}

Outcode BatchSetup::run(const SubmittedBatch& batch) {
    return vertexStage_.run(batch, ViewportTransform(*batch.state, framebuffer_.height()));
}

Batch BatchSetup::stage(const SubmittedBatch& batch) {
    run(batch);
    return vertexStage_.assemble(batch);
}

void BatchSetup::setUp(const SubmittedBatch& batch, TriangleTarget& target, Stats& stats) {
    Outcode anyOutside = run(batch);
    const bool indexed = !batch.indices.empty();
    const std::span<const Outcode> outcodes = vertexStage_.outcodes();
    // The outcode of the primitive's i-th vertex: an indexed batch's vertices include some it
    // does not draw.
    const auto outcodeAt = [&](std::uint32_t i) { return outcodes[indexed ? batch.indices[i] : i]; };
    if (indexed && anyOutside != 0) {
        anyOutside = 0;
        for (std::uint32_t i = 0; i < batch.indices.size(); ++i) anyOutside |= outcodeAt(i);
    }
    const ViewportTransform viewport(*batch.state, framebuffer_.height());
    const bool v1v3Quads =
        (batch.state->shadeModel == ShadeModel::Flat && batch.colorsPerVertex) || batch.quadSplit == QuadSplit::V1V3;
    const bool drawModuleFills = fillsThroughDrawModule(*batch.state);
    FragmentKey key = triangleFragmentKey(*batch.state, batch.methods);
    // (Two-sided lighting gives back faces other colours, unchecked.)
    if (vertexStage_.alphaOne() && !batch.state->twoSidedColors) key = withAlphaOne(key);
    const bool drawModuleOffsets = drawModuleFills && key.depthOffset;
    key.depthOffset = key.depthOffset && !drawModuleOffsets;
    const FragmentChoice fragments(bestFragmentPaths(), key, *batch.state);
    const std::span<const ClipVertex> assembled =
        batch.methods.needsEyeSpace() ? vertexStage_.assemble(batch).vertices : std::span<const ClipVertex>{};
    const PixelRect drawable =
        drawableRect(batch.state->fragmentOps.scissor, framebuffer_.width(), framebuffer_.height());
    const bool stagedSnaps = !batch.state->twoSidedColors && !drawModuleOffsets &&
                             !(batch.state->secondaryColors && batch.state->shadeModel == ShadeModel::Flat);
    // The vertices first .. first + count, on the direct path or through the draw module.
    const auto decompose = [&](std::uint32_t first, std::uint32_t count, Outcode outside) {
        const DecompositionPath path =
            outside == 0 && !drawModuleFills ? DecompositionPath::Direct : DecompositionPath::DrawModule;
        const bool drawModuleCulls = path == DecompositionPath::DrawModule && batch.state->cullEnabled &&
                                     batch.methods.culling == CullMethod::WindowArea;
        const Call call{batch,       batch.vertices,    assembled,      &target, stats,
                        &fragments,  drawModuleCulls,   nullptr,        nullptr, drawable,
                        stagedSnaps, drawModuleOffsets, drawModuleFills};
        decomposeTriangles(batch.mode, count, path, v1v3Quads, [&](TriangleIndices t) {
            for (std::uint32_t& v : t.v) v = indexed ? batch.indices[v + first] : v + first;
            setUpTriangle(call, t, viewport);
        });
    };
    const auto count = static_cast<std::uint32_t>(indexed ? batch.indices.size() : batch.vertices.size());
    if (batch.mode != PrimitiveMode::Quads || anyOutside == 0 || drawModuleFills || count <= kQuadSegmentVertices) {
        return decompose(0, count, anyOutside);
    }
    // The reference's draw module takes a long draw of quads in segments of 4096 vertices and
    // chooses the path per segment: one without a vertex to clip goes the direct way, and its
    // quads are split along the other diagonal (measured with OSMesa).
    for (std::uint32_t first = 0; first < count; first += kQuadSegmentVertices) {
        const std::uint32_t size = std::min(kQuadSegmentVertices, count - first);
        Outcode segmentOutside = 0;
        for (std::uint32_t i = first; i < first + size; ++i) segmentOutside |= outcodeAt(i);
        decompose(first, size, segmentOutside);
    }
}

void BatchSetup::select(const SubmittedBatch& batch, HitRange& hits, FeedbackOutput* feedback, Stats& stats) {
    run(batch);
    const ViewportTransform viewport(*batch.state, framebuffer_.height());
    const bool v1v3Quads =
        (batch.state->shadeModel == ShadeModel::Flat && batch.colorsPerVertex) || batch.quadSplit == QuadSplit::V1V3;
    const std::span<const ClipVertex> assembled =
        batch.methods.needsEyeSpace() ? vertexStage_.assemble(batch).vertices : std::span<const ClipVertex>{};
    const Call call{batch,
                    batch.vertices,
                    assembled,
                    nullptr,
                    stats,
                    nullptr,
                    batch.state->cullEnabled,
                    feedback ? nullptr : &hits,
                    feedback};
    decomposeTriangles(batch.mode, static_cast<std::uint32_t>(batch.vertices.size()), DecompositionPath::DrawModule,
                       v1v3Quads, [&](const TriangleIndices& t) { setUpTriangle(call, t, viewport); });
}

void BatchSetup::setUpTriangle(const Call& call, const TriangleIndices& t, const ViewportTransform& viewport) {
    const BatchHeader& batch = call.batch;
    const std::span<const Outcode> outcodes = vertexStage_.outcodes();
    const std::span<const WindowVertex> windowVertices = vertexStage_.windowVertices();
    ++call.stats.triangles;
    if (batch.methods.culling != CullMethod::WindowArea && batch.state->cullEnabled) {
        const auto& eye = call.assembled;
        const Facing facing =
            seedFacing(batch.methods.culling, eye[t.v[0]], eye[t.v[1]], eye[t.v[2]], batch.state->frontFaceCCW);
        if (facing != Facing::ZeroArea && isCulled(*batch.state, facing)) {  // edge-on: the seeds keep it
            return countCulled(call.stats, facing);
        }
    }
    const Vertex& provoking = call.vertices[t.v[2]];
    const Outcode outsideAny = outcodes[t.v[0]] | outcodes[t.v[1]] | outcodes[t.v[2]];
    if (outsideAny == 0) {
        if (call.stagedSnaps) return setUpStaged(call, t, provoking.color);
        const auto lit = [&](std::uint32_t i) { return &vertexStage_.lightingOutputsOf(i); };
        setUpSidedTriangle(call, {&windowVertices[t.v[0]], &windowVertices[t.v[1]], &windowVertices[t.v[2]]},
                           std::array{lit(t.v[0]), lit(t.v[1]), lit(t.v[2])}, provoking.color, *lit(t.v[2]));
        return;
    }
    if (outcodes[t.v[0]] & outcodes[t.v[1]] & outcodes[t.v[2]]) {
        ++call.stats.clippedAway;
        return;
    }
    const ClippedPolygon polygon =
        clipTriangle(vertexStage_.clipVertex(call.vertices, t.v[0]), vertexStage_.clipVertex(call.vertices, t.v[1]),
                     vertexStage_.clipVertex(call.vertices, t.v[2]), outsideAny, batch.state->clipPlanes);
    if (polygon.count < 3) {
        ++call.stats.clippedAway;
        return;
    }
    call.stats.clipCreated += static_cast<std::uint64_t>(polygon.count - 3);
    // Input vertices keep the window position of the vertex stage; new ones get the clipper's.
    const auto window = [&](int i) {
        const int source = polygon.source[static_cast<std::size_t>(i)];
        return source == kNewVertex ? viewport.applyToClipped(polygon.vertices[static_cast<std::size_t>(i)])
                                    : windowVertices[t.v[source]];
    };
    const WindowVertex first = window(0);
    WindowVertex previous = window(1);
    const auto& clipped = polygon.vertices;
    for (int i = 2; i < polygon.count; ++i) {
        const WindowVertex current = window(i);
        const auto k = static_cast<std::size_t>(i);
        setUpSidedTriangle(call, {&previous, &current, &first}, std::array{&clipped[k - 1], &clipped[k], &clipped[0]},
                           provoking.color, vertexStage_.lightingOutputsOf(t.v[2]));
        previous = current;
    }
}

// With two-sided lighting a triangle that setup finds facing back (its fixed-point area, after
// clipping) takes the back colours: the reference picks them in the fragment shader by
// gl_FrontFacing, both colours interpolated as usual. Under flat shading every vertex takes the
// provoking vertex's secondary colour (the primary one goes as the flat colour).
template <class Record>
void BatchSetup::setUpSidedTriangle(const Call& call, const std::array<const WindowVertex*, 3>& window,
                                    std::array<const Record*, 3> records, const glm::vec4& provokingColor,
                                    const LightingOutputs& provoking) {
    const DrawState& state = *call.batch.state;
    const bool back =
        state.twoSidedColors &&
        (call.drawModuleSides ? drawModuleFacesBack(*window[0], *window[1], *window[2], state.frontFaceCCW)
                              : facingOf(fixedArea(snap(*window[0]), snap(*window[1]), snap(*window[2])),
                                         state.frontFaceCCW) == Facing::Back);
    const glm::vec4& flatColor = back ? provoking.backColor : provokingColor;
    const bool flatSecondary = state.secondaryColors && state.shadeModel == ShadeModel::Flat;
    if (!back && !flatSecondary) return setUpTriangle(call, *window[0], *window[1], *window[2], flatColor);
    std::array<WindowVertex, 3> changed{*window[0], *window[1], *window[2]};
    for (std::size_t i = 0; i < 3; ++i) {
        if (back) changed[i].color = records[i]->backColor;
        if (state.secondaryColors) {
            const glm::vec3& own = back ? records[i]->backSecondaryColor : records[i]->secondaryColor;
            const glm::vec3& flat = back ? provoking.backSecondaryColor : provoking.secondaryColor;
            changed[i].secondaryColor = flatSecondary ? flat : own;
        }
    }
    setUpTriangle(call, changed[0], changed[1], changed[2], flatColor);
}

void BatchSetup::setUpTriangle(const BatchHeader& batch, const WindowVertex& v0, const WindowVertex& v1,
                               const WindowVertex& v2, const glm::vec4& flatColor, TriangleTarget& target,
                               Stats& stats) {
    FragmentKey key = triangleFragmentKey(*batch.state, batch.methods);
    key.depthOffset = false;
    const FragmentChoice fragments(bestFragmentPaths(), key, *batch.state);
    const PixelRect drawable =
        drawableRect(batch.state->fragmentOps.scissor, framebuffer_.width(), framebuffer_.height());
    setUpTriangle(Call{batch, {}, {}, &target, stats, &fragments, false, nullptr, nullptr, drawable}, v0, v1, v2,
                  flatColor);
}

// Snaps, culls by the fixed-point area and prepares one triangle in window coordinates.
void BatchSetup::setUpTriangle(const Call& call, const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                               const glm::vec4& flatColor) {
    const DrawState& state = *call.batch.state;
    if (!areUsable(v0, v1, v2)) {
        ++call.stats.clippedAway;
        return;
    }
    if (call.drawModuleCulls) {
        const float determinant = drawModuleDeterminant(v0, v1, v2);
        const Facing facing = drawModuleFacing(determinant, state.frontFaceCCW);
        if (isCulled(state, facing)) {
            return countCulled(call.stats, facing);
        }
        // Selection's cull stage drops a triangle of no area too (measured with OSMesa).
        if ((call.hits || call.feedback) && determinant == 0.0f) return;
    }
    if (call.hits) {
        call.hits->add(v0.z), call.hits->add(v1.z), call.hits->add(v2.z);
        return;
    }
    if (call.feedback) {
        call.feedback->triangle(v0, v1, v2);
        return;
    }
    const auto setUpAt = [&](const WindowVertex& a, const WindowVertex& b, const WindowVertex& c) {
        SetupTriangle triangle{{&a, &b, &c}, {snap(a), snap(b), snap(c)}, 0, &flatColor};
        setUpSnapped(call, triangle);
    };
    if (call.drawModuleOffsets) {  // the draw module's offset stage moves the vertices themselves
        std::array<WindowVertex, 3> offset{v0, v1, v2};
        offsetInDrawModule(state.polygonOffset, offset[0], offset[1], offset[2]);
        return setUpAt(offset[0], offset[1], offset[2]);
    }
    setUpAt(v0, v1, v2);
}

void BatchSetup::setUpStaged(const Call& call, const TriangleIndices& t, const glm::vec4& flatColor) {
    const std::span<const SnappedVertex> snapped = vertexStage_.snapped();
    const SnappedVertex &s0 = snapped[t.v[0]], &s1 = snapped[t.v[1]], &s2 = snapped[t.v[2]];
    if (!(s0.usable && s1.usable && s2.usable)) {
        ++call.stats.clippedAway;
        return;
    }
    const std::span<const WindowVertex> window = vertexStage_.windowVertices();
    const WindowVertex &w0 = window[t.v[0]], &w1 = window[t.v[1]], &w2 = window[t.v[2]];
    if (call.drawModuleCulls) {  // as setUpTriangle's
        const DrawState& state = *call.batch.state;
        const Facing facing = drawModuleFacing(drawModuleDeterminant(w0, w1, w2), state.frontFaceCCW);
        if (isCulled(state, facing)) return countCulled(call.stats, facing);
    }
    SetupTriangle triangle{{&w0, &w1, &w2}, {s0.fixed, s1.fixed, s2.fixed}, 0, &flatColor};
    setUpSnapped(call, triangle);
}

void BatchSetup::setUpSnapped(const Call& call, SetupTriangle& triangle) {
    const DrawState& state = *call.batch.state;
    const Methods& methods = call.batch.methods;
    triangle.area = fixedArea(triangle.fixed[0], triangle.fixed[1], triangle.fixed[2]);
    const Facing facing = facingOf(triangle.area, state.frontFaceCCW);
    if (facing == Facing::ZeroArea) {
        ++call.stats.culledZeroArea;
        return;
    }
    // The seeds' culling methods have decided already, before clipping.
    if (methods.culling == CullMethod::WindowArea && isCulled(state, facing)) {
        return countCulled(call.stats, facing);
    }
    ++call.stats.rasterized;
    if (prepareTriangle(triangle, *call.fragments, methods.raster, call.drawable, call.target->slot())) {
        call.target->keep();
    }
}

}  // namespace glrenderer
