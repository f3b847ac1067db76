#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "glrenderer/draw_state.h"
#include "glrenderer/state_interner.h"
#include "glrenderer/lighting.h"
#include "glrenderer/methods.h"
#include "glrenderer/pipeline.h"
#include "glrenderer/stats.h"
#include "clip_vertex.h"
#include "glrenderer/vertex.h"
#include "glrenderer/append_array.h"
#include "raster_triangle.h"

namespace glrenderer {

// What a draw is, as the reference sees it: consecutive submissions of one mode under one
// state, merged, with the methods in force when they were submitted.
struct BatchHeader {
    StateRef state;  // as drawn: flat when the reference draws the batch flat (Pipeline::closeBatch)
    VertexTransform transform;
    Methods methods;
    PrimitiveMode mode = PrimitiveMode::Points;
    QuadSplit quadSplit = QuadSplit::ByPath;
    bool colorsPerVertex = false;  // glColor was called inside its glBegin/glEnd blocks
    // The reference's vertex format holds a colour (glColor inside a glBegin/glEnd since the
    // last flush): its fragment shader then interpolates the colour, even one set outside.
    bool colorInFormat = false;
    // Its vertices carry edge flags in the reference's vertex format (glEdgeFlag since the last
    // flush). Without them, the current edge flag, false, hides every edge: the reference then
    // culls the faces drawn as lines or points, whole (Mesa's _PolygonModeAlwaysCulls).
    bool edgeFlagsPerVertex = false;
    // Lights the batch's vertices in the vertex stage (lightChunk); null when they are unlit or
    // were lit by the program's thread. Owned by the pipeline until the batch is drawn.
    const VertexLighting* lighting = nullptr;
};

// Whether a batch's state reads its vertices' LightingOutputs (the back or secondary colours).
inline bool needsLightingOutputs(const DrawState& state) { return state.twoSidedColors || state.secondaryColors; }

// One draw with its vertices as the program gave them. An indexed one (a part of glDrawElements)
// draws the vertices its `indices` name, in their order; the others draw `vertices` in order.
struct SubmittedBatch : BatchHeader {
    std::span<const Vertex> vertices;
    std::span<const std::uint32_t> indices;
    std::span<const LightingOutputs> lightingOutputs;  // one per vertex with needsLightingOutputs, else none
};

// One draw after the vertex stage, its vertices assembled (VertexStage::assemble).
struct Batch : BatchHeader {
    std::span<const ClipVertex> vertices;
};

// A batch's place in its chunk.
struct BatchEntry : BatchHeader {
    std::size_t first = 0, count = 0;            // its vertices in the chunk
    std::size_t firstIndex = 0, indexCount = 0;  // its indices in the chunk (none: not indexed)
};

// The vertices a chunk is made for: a part of a long primitive (Pipeline::kPartVertices) plus
// the batch that crossed it, in the usual case.
inline constexpr std::size_t kChunkVertices = 2 * Pipeline::kPartVertices;

// Consecutive batches with their vertices in one array: what the pipeline hands to its batch
// thread at once, so that a thousand small draws cost one hand-over. Chunks are reused frame
// after frame, keeping their capacity.
struct BatchChunk {
    BatchChunk(std::size_t vertexCapacity, std::size_t batchCapacity) {
        vertices.reserve(vertexCapacity);
        batches.reserve(batchCapacity);
        indices.reserve(vertexCapacity);
        setUpTriangles.reserve(vertexCapacity);  // strips and fans: a triangle per vertex
    }

    AppendArray<Vertex> vertices;
    // Beside `vertices`, index for index, as far as the last batch that needs them
    // (needsLightingOutputs): lit by lightChunk or on the program's thread, zeros when unlit.
    AppendArray<LightingOutputs> lightingOutputs;
    AppendArray<std::uint32_t> indices;  // of its indexed batches, into their own vertices
    std::vector<BatchEntry> batches;
    bool lit = false;  // lightChunk has lit its batches' vertices
    // Set when the chunk's poster has set its triangles up (BatchSetup, into slots of the
    // tiles' TriangleArena), as it does when the batch thread is behind: drawing the chunk then
    // only queues `setUpTriangles` and adds `setupStats`.
    bool setUp = false;
    std::vector<const RasterTriangle*> setUpTriangles;
    Stats setupStats;

    // The entry's batch with its vertices and indices.
    SubmittedBatch batch(const BatchEntry& entry) const {
        const bool outputs = needsLightingOutputs(*entry.state) && lightingOutputs.size() >= entry.first + entry.count;
        return {entry, std::span<const Vertex>(vertices).subspan(entry.first, entry.count),
                std::span<const std::uint32_t>(indices).subspan(entry.firstIndex, entry.indexCount),
                outputs ? std::span<const LightingOutputs>(lightingOutputs).subspan(entry.first, entry.count)
                        : std::span<const LightingOutputs>{}};
    }
    // The outputs of vertices first .. first + count, the array grown to them (not initialized).
    std::span<LightingOutputs> outputsOf(std::size_t first, std::size_t count) {
        if (lightingOutputs.size() < first + count)
            lightingOutputs.appendUninitialized(first + count - lightingOutputs.size());
        return std::span(lightingOutputs).subspan(first, count);
    }
    // As many outputs as `count` vertices: cut, or grown with outputs not initialized.
    void resizeOutputs(std::size_t count) {
        if (lightingOutputs.size() > count) lightingOutputs.truncate(count);
        outputsOf(0, count);
    }
    void clear() {
        vertices.clear();
        lightingOutputs.clear();
        indices.clear();
        batches.clear();
        lit = false;
        setUp = false;
        setUpTriangles.clear();
        setupStats = {};
    }
};

}  // namespace glrenderer
