#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "batch.h"
#include "feedback_output.h"
#include "fragment_paths.h"
#include "pixel_rect.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/hit_range.h"
#include "glrenderer/stats.h"
#include "triangle_arena.h"
#include "vertex_stage.h"
#include "window_vertex.h"

namespace glrenderer {

struct TriangleIndices;

// Turns the triangles of a batch into RasterTriangles: vertex stage, window transform,
// decomposition, clipping, culling and setup. It touches no pixels, so it runs on whichever thread has time;
// the triangles go to a target, and what it counts to a Stats, both given per batch.
class BatchSetup {
public:
    // Its scratch arrays are sized for `batchVertices`, so that a batch of up to that many
    // allocates nothing, however rarely this instance is used.
    BatchSetup(const Framebuffer& framebuffer, std::size_t batchVertices)
        : framebuffer_(framebuffer), vertexStage_(batchVertices) {}

    // Whether setUp() takes the batch: filled triangles to draw (the unfilled stage draws lines at
    // once).
    static bool handles(const BatchHeader& batch);
    static bool filled(const DrawState& state) {
        return state.polygonFront == PolygonMode::Fill && state.polygonBack == PolygonMode::Fill;
    }
    // The whole batch.
    void setUp(const SubmittedBatch& batch, TriangleTarget& target, Stats& stats);
    // GL_SELECT: the batch's triangles that survive clipping and culling add their window depths
    // to `hits` instead of being set up.
    // GL_FEEDBACK (`feedback` not null): they go to `feedback`.
    void select(const SubmittedBatch& batch, HitRange& hits, FeedbackOutput* feedback, Stats& stats);
    // Every batch of the chunk, into `writer`'s slots listed in the chunk and the chunk's
    // counts, if it handles them all; returns whether it did.
    bool setUp(BatchChunk& chunk, ArenaWriter& writer);

    // The batch through the vertex stage with every vertex assembled, for the stages that draw at
    // once and the unfilled stage (which decomposes and clips the batch itself), with its
    // vertices' outcodes and window positions; all kept until the next batch.
    Batch stage(const SubmittedBatch& batch);
    std::span<const Outcode> outcodes() const { return vertexStage_.outcodes(); }
    std::span<const WindowVertex> windowVertices() const { return vertexStage_.windowVertices(); }
    // The setup of one filled triangle the unfilled stage has clipped (and offset: the draw
    // module's offset stage moves its vertices, so setup adds no offset of its own).
    void setUpTriangle(const BatchHeader& batch, const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                       const glm::vec4& flatColor, TriangleTarget& target, Stats& stats);

private:
    struct Call {
        const BatchHeader& batch;
        std::span<const Vertex> vertices;       // as the program gave them
        std::span<const ClipVertex> assembled;  // only when the culling method needs eye space
        TriangleTarget* target;                 // null in GL_SELECT
        Stats& stats;
        const FragmentChoice* fragments;  // the batch's, chosen once; null in GL_SELECT
        // The batch goes through the reference's draw module with culling on: its cull stage
        // decides first, by drawModuleFacing.
        bool drawModuleCulls = false;
        HitRange* hits = nullptr;            // GL_SELECT
        FeedbackOutput* feedback = nullptr;  // GL_FEEDBACK
        PixelRect drawable{};                // drawableRect of the draw, when drawing
        // The triangles whose vertices are the stage's take its snaps as they are: no selection,
        // feedback, back colours, flat secondary colours or draw-module offset (draw-module
        // culling, by their window vertices, comes first).
        bool stagedSnaps = false;
        // The draw module's offset stage offsets the triangles' vertices (fillsThroughDrawModule
        // with GL_POLYGON_OFFSET_FILL), not setup their fragments.
        bool drawModuleOffsets = false;
        // The draw module's two-sided stage picks the back colours, by its determinant
        // (fillsThroughDrawModule), not the rasterizer by setup's area.
        bool drawModuleSides = false;
    };
    void setUpTriangle(const Call& call, const TriangleIndices& triangle, const ViewportTransform& viewport);
    // A triangle's window vertices (by address: most triangles take them as they are) with the
    // records of their back and secondary colours (LightingOutputs or ClipVertex), and its
    // provoking vertex's colours, for its flat colours.
    template <class Record>
    [[gnu::always_inline]] inline void setUpSidedTriangle(const Call& call,
                                                          const std::array<const WindowVertex*, 3>& window,
                                                          std::array<const Record*, 3> records,
                                                          const glm::vec4& provokingColor,
                                                          const LightingOutputs& provoking);
    Outcode run(const SubmittedBatch& batch);
    // (Inlined into the callers: it is most of the work per triangle, called once each.)
    [[gnu::always_inline]] inline void setUpTriangle(const Call& call, const WindowVertex& v0, const WindowVertex& v1,
                                                     const WindowVertex& v2, const glm::vec4& flatColor);
    // The same for a triangle of the stage's vertices, with their snaps (Call::stagedSnaps).
    [[gnu::always_inline]] inline void setUpStaged(const Call& call, const TriangleIndices& triangle,
                                                   const glm::vec4& flatColor);
    // Their common end: culls by the fixed-point area and prepares the snapped triangle.
    [[gnu::always_inline]] inline void setUpSnapped(const Call& call, SetupTriangle& triangle);

    const Framebuffer& framebuffer_;  // for its size only
    VertexStage vertexStage_;
};

}  // namespace glrenderer
