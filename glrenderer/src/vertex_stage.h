#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "batch.h"
#include "clip.h"
#include "clip_vertex.h"
#include "triangle_setup.h"
#include "window_vertex.h"

namespace glrenderer {

// The vertex stage, per batch on the pipeline's side, in one pass over the program's vertices:
// each one to clip space with the batch's matrices, its clip outcode and its window position.
// Whole ClipVertex records (what the clipper and the stages that draw at once take) are
// assembled from these only when asked: most triangles never need one.
class VertexStage {
public:
    // Its arrays are sized for `batchVertices`, so that a batch of up to that many allocates nothing.
    explicit VertexStage(std::size_t batchVertices);

    // Stages the batch (snapping each window vertex once); returns the union of its vertices' outcodes (with the
    // program's clip planes: the pass computes the view volume's, a second one adds those when enabled) and, with fog
    // and texturing, gives the window vertices their fog and texture coordinates. The arrays below hold the batch's
    // vertices until the next call.
    Outcode run(const SubmittedBatch& batch, const ViewportTransform& viewport);
    std::span<const Outcode> outcodes() const { return outcodes_; }
    std::span<const WindowVertex> windowVertices() const { return windowVertices_; }
    // Each window vertex snapped, and whether it can be set up (snapVertex).
    std::span<const SnappedVertex> snapped() const { return snapped_; }
    // Whether every window vertex's colour has alpha 1 (FragmentKey::alphaOne).
    bool alphaOne() const { return alphaOne_; }

    // Vertex i's back and secondary colours in the batch last run: zeros when its state has none.
    const LightingOutputs& lightingOutputsOf(std::size_t i) const {
        static constexpr LightingOutputs kNone;
        return outputs_.empty() ? kNone : outputs_[i];
    }
    // Vertex i of the batch last run (`vertices` its program's vertices), as the clipper takes it (without eye space).
    ClipVertex clipVertex(std::span<const Vertex> vertices, std::size_t i) const;
    // Every vertex of the batch last run, with eye-space positions and normals when its culling
    // method looks at them (Methods::needsEyeSpace); valid until the next call.
    Batch assemble(const SubmittedBatch& batch);

private:
    std::vector<glm::vec4> clipPositions_;
    std::vector<float> fogCoordinates_;      // empty without fog
    std::vector<glm::vec4> texCoordinates_;  // empty without texturing
    std::vector<Outcode> outcodes_;
    std::vector<WindowVertex> windowVertices_;
    std::vector<SnappedVertex> snapped_;
    bool alphaOne_ = false;
    std::vector<ClipVertex> clipVertices_;
    std::span<const LightingOutputs> outputs_;   // the batch's, with needsLightingOutputs
    std::vector<LightingOutputs> unlitOutputs_;  // zeros, for such a batch left unlit
};

// The vertex stage's lighting, on the pipeline's side: the vertices of the chunk's lit batches
// (BatchHeader::lighting) lit in place, once (the first of the chunk's consumers to come calls it).
void lightChunk(BatchChunk& chunk);

// The pass itself, into arrays as long as `vertices`: clip position (the MVP applied by
// ColumnTransform), clipOutcode and ViewportTransform::apply. Returns the union of the outcodes
// and whether every colour has alpha 1 (VertexStage::alphaOne).
// CPUs with FMA take a version that works on two vertices' coordinates at once (without FMA,
// apply()'s fused multiply-adds are library calls); the bits are the same.
struct StagedVertices {
    glm::vec4* clipPositions;
    Outcode* outcodes;
    WindowVertex* windowVertices;
};
struct StagedSummary {
    Outcode anyOutside = 0;
    bool alphaOne = true;
};
StagedSummary stageVertices(std::span<const Vertex> vertices, const Matrix& modelviewProjection,
                            const ViewportTransform& viewport, const StagedVertices& out);

// The version for CPUs with FMA, compiled for them; only call it after cpuHasFma().
StagedSummary stageVerticesFma(std::span<const Vertex> vertices, const Matrix& modelviewProjection,
                               const ViewportTransform& viewport, const StagedVertices& out);

}  // namespace glrenderer
