#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "batch.h"
#include "clip_vertex.h"
#include "window_vertex.h"

namespace glrenderer {

// The vertex stage's first half, per batch on the pipeline's side: the vertices from object to
// clip space with the batch's matrices, and eye-space positions and normals when its culling
// method looks at them.
class VertexStage {
public:
    // Its array is sized for `batchVertices`, so that a batch of up to that many allocates nothing.
    explicit VertexStage(std::size_t batchVertices) { clipVertices_.reserve(batchVertices); }

    // The batch in clip space; its vertices stay valid until the next call.
    Batch toClipSpace(const SubmittedBatch& batch);

private:
    std::vector<ClipVertex> clipVertices_;
};

// The second half: each vertex's clip outcode (clipOutcode) and window position
// (ViewportTransform::apply), into arrays as long as `vertices`. Returns the union of the
// outcodes. CPUs with FMA take a version that works on a vertex's four coordinates at once
// (without FMA, apply()'s fused multiply-adds are library calls); the bits are the same.
std::uint8_t transformVertices(std::span<const ClipVertex> vertices, const ViewportTransform& viewport,
                               std::uint8_t* outcodes, WindowVertex* windowVertices);

// The version for CPUs with FMA, compiled for them; only call it after cpuHasFma().
std::uint8_t transformVerticesFma(std::span<const ClipVertex> vertices, const ViewportTransform& viewport,
                                  std::uint8_t* outcodes, WindowVertex* windowVertices);

}  // namespace glrenderer
