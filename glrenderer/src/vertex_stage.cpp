#include "vertex_stage.h"

#include "clip.h"
#include "cpu_features.h"

namespace glrenderer {
namespace {

// The normal in eye space as the seeds computed it: by the modelview's upper 3x3.
glm::vec3 eyeNormal(const Matrix& m, const glm::vec3& n) {
    return {at(m, 0, 0) * n.x + at(m, 0, 1) * n.y + at(m, 0, 2) * n.z,
            at(m, 1, 0) * n.x + at(m, 1, 1) * n.y + at(m, 1, 2) * n.z,
            at(m, 2, 0) * n.x + at(m, 2, 1) * n.y + at(m, 2, 2) * n.z};
}

}  // namespace

Batch VertexStage::toClipSpace(const SubmittedBatch& batch) {
    const std::size_t count = batch.vertices.size();
    clipVertices_.resize(count);
    const VertexTransform& t = batch.transform;
    const bool eyeSpace = batch.methods.needsEyeSpace();
    for (std::size_t i = 0; i < count; ++i) {
        const Vertex& in = batch.vertices[i];
        ClipVertex& out = clipVertices_[i];
        out.position = transform(t.modelviewProjection, in.position);
        out.color = in.color;
        out.edgeFlag = in.edgeFlag;
        if (eyeSpace) {
            out.eye = glm::vec3(transform(t.modelview, in.position));
            out.normal = eyeNormal(t.modelview, in.normal);
        }
    }
    return Batch{batch, clipVertices_};
}

std::uint8_t transformVertices(std::span<const ClipVertex> vertices, const ViewportTransform& viewport,
                               std::uint8_t* outcodes, WindowVertex* windowVertices) {
    if (cpuHasFma()) return transformVerticesFma(vertices, viewport, outcodes, windowVertices);
    std::uint8_t anyOutside = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        outcodes[i] = clipOutcode(vertices[i].position);
        anyOutside |= outcodes[i];
        windowVertices[i] = viewport.apply(vertices[i]);
    }
    return anyOutside;
}

}  // namespace glrenderer
