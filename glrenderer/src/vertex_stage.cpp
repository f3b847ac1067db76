#include "vertex_stage.h"

#include "clip.h"
#include "column_transform.h"
#include "cpu_features.h"
#include "fog.h"
#include "texture_coordinates.h"

namespace glrenderer {
namespace {

// The normal in eye space as the seeds computed it: by the modelview's upper 3x3.
glm::vec3 eyeNormal(const Matrix& m, const glm::vec3& n) {
    return {at(m, 0, 0) * n.x + at(m, 0, 1) * n.y + at(m, 0, 2) * n.z,
            at(m, 1, 0) * n.x + at(m, 1, 1) * n.y + at(m, 1, 2) * n.z,
            at(m, 2, 0) * n.x + at(m, 2, 1) * n.y + at(m, 2, 2) * n.z};
}

}  // namespace

VertexStage::VertexStage(std::size_t batchVertices) {
    clipPositions_.reserve(batchVertices);
    fogCoordinates_.reserve(batchVertices);
    texCoordinates_.reserve(batchVertices);
    outcodes_.reserve(batchVertices);
    windowVertices_.reserve(batchVertices);
    snapped_.reserve(batchVertices);
    clipVertices_.reserve(batchVertices);
    unlitOutputs_.reserve(batchVertices);
}

Outcode VertexStage::run(const SubmittedBatch& batch, const ViewportTransform& viewport) {
    const std::size_t count = batch.vertices.size();
    clipPositions_.resize(count);
    outcodes_.resize(count);
    windowVertices_.resize(count);
    const StagedVertices out{clipPositions_.data(), outcodes_.data(), windowVertices_.data()};
    const Matrix& mvp = batch.transform.modelviewProjection;
    const StagedSummary staged = cpuHasFma() ? stageVerticesFma(batch.vertices, mvp, viewport, out)
                                             : stageVertices(batch.vertices, mvp, viewport, out);
    Outcode anyOutside = staged.anyOutside;
    alphaOne_ = staged.alphaOne;
    snapped_.resize(count);
    for (std::size_t i = 0; i < count; ++i) snapped_[i] = snapVertex(windowVertices_[i]);
    fogCoordinates_.clear();
    if (batch.state->fog.mode != FogMode::Off) {
        fogCoordinates_.resize(count);
        fogCoordinates(batch.vertices, batch.transform.modelview, batch.state->fog.distance, fogCoordinates_);
        for (std::size_t i = 0; i < count; ++i) windowVertices_[i].fogCoord = fogCoordinates_[i];
    }
    texCoordinates_.clear();
    if (batch.state->texture.env != TextureEnv::Off) {
        texCoordinates_.resize(count);
        textureCoordinates(batch.vertices, batch.state->texture, batch.transform.modelview, texCoordinates_);
        for (std::size_t i = 0; i < count; ++i) windowVertices_[i].texCoord = texCoordinates_[i];
    }
    outputs_ = {};
    if (needsLightingOutputs(*batch.state)) {
        outputs_ = batch.lightingOutputs;
        if (outputs_.size() != count) {
            unlitOutputs_.assign(count, LightingOutputs{});
            outputs_ = unlitOutputs_;
        }
        if (batch.state->secondaryColors) {
            for (std::size_t i = 0; i < count; ++i) windowVertices_[i].secondaryColor = outputs_[i].secondaryColor;
        }
    }
    const UserClipPlanes& user = batch.state->clipPlanes;
    if (user.enabled) {
        for (std::size_t i = 0; i < count; ++i) {
            outcodes_[i] |= userClipOutcode(clipPositions_[i], user);
            anyOutside |= outcodes_[i];
        }
    }
    return anyOutside;
}

ClipVertex VertexStage::clipVertex(std::span<const Vertex> vertices, std::size_t i) const {
    const Vertex& in = vertices[i];
    ClipVertex out;
    out.position = clipPositions_[i];
    out.color = in.color;
    const LightingOutputs& lit = lightingOutputsOf(i);
    out.backColor = lit.backColor;
    out.secondaryColor = lit.secondaryColor;
    out.backSecondaryColor = lit.backSecondaryColor;
    out.edgeFlag = in.edgeFlag;
    if (!fogCoordinates_.empty()) out.fogCoord = fogCoordinates_[i];
    if (!texCoordinates_.empty()) out.texCoord = texCoordinates_[i];
    return out;
}

Batch VertexStage::assemble(const SubmittedBatch& batch) {
    const std::size_t count = batch.vertices.size();
    clipVertices_.resize(count);
    for (std::size_t i = 0; i < count; ++i) clipVertices_[i] = clipVertex(batch.vertices, i);
    if (batch.methods.needsEyeSpace()) {
        const Matrix& modelview = batch.transform.modelview;
        for (std::size_t i = 0; i < count; ++i) {
            clipVertices_[i].eye = glm::vec3(transform(modelview, batch.vertices[i].position));
            clipVertices_[i].normal = eyeNormal(modelview, batch.vertices[i].normal);
        }
    }
    return Batch{batch, clipVertices_};
}

void lightChunk(BatchChunk& chunk) {
    if (chunk.lit) return;
    chunk.lit = true;
    for (const BatchEntry& batch : chunk.batches) {
        if (batch.lighting) {
            const std::span<LightingOutputs> outputs = needsLightingOutputs(*batch.state)
                                                           ? chunk.outputsOf(batch.first, batch.count)
                                                           : std::span<LightingOutputs>{};
            batch.lighting->lightVertices(std::span(chunk.vertices).subspan(batch.first, batch.count), outputs,
                                          batch.state->twoSidedColors);
        }
    }
}

StagedSummary stageVertices(std::span<const Vertex> vertices, const Matrix& modelviewProjection,
                            const ViewportTransform& viewport, const StagedVertices& out) {
    const ColumnTransform toClip(modelviewProjection);
    StagedSummary summary;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (i + kVertexFetchAhead < vertices.size()) __builtin_prefetch(&vertices[i + kVertexFetchAhead]);
        glm::vec4& clip = out.clipPositions[i];
        _mm_storeu_ps(&clip.x, toClip.apply(vertices[i].position));
        out.outcodes[i] = clipOutcode(clip);
        summary.anyOutside |= out.outcodes[i];
        summary.alphaOne &= vertices[i].color.a == 1.0f;
        out.windowVertices[i] = viewport.apply(clip, vertices[i].color);
    }
    return summary;
}

}  // namespace glrenderer
