#include "batch_drawer.h"

#include "decompose.h"
#include "feedback_output.h"
#include "vertex_stage.h"
#include "points_lines.h"
#include "unfilled.h"

namespace glrenderer {
namespace {

// Whether a batch may show edges in line or point mode: its vertices carry edge flags of their
// own, or the current one they all took is true (drawUnfilledBatch).
bool anyEdgeShown(const Batch& batch) {
    return batch.edgeFlagsPerVertex || batch.vertices.empty() || batch.vertices.front().edgeFlag;
}

}  // namespace

BatchDrawer::BatchDrawer(Framebuffer& framebuffer)
    : framebuffer_(framebuffer), tiles_(framebuffer), setup_(framebuffer, kChunkVertices) {
    texturesInUse_.reserve(kTexturesReserved);
}

void BatchDrawer::flush() {
    tiles_.flush(stats_, paintersSort_);
    texturesInUse_.clear();
}

void BatchDrawer::keepTexture(const TextureState& texture) {
    if (texture.env == TextureEnv::Off) return;
    if (texturesInUse_.empty() || texturesInUse_.back() != texture.texture) texturesInUse_.push_back(texture.texture);
}

void BatchDrawer::draw(const SubmittedBatch& submitted) {
    if (submitted.state->selection || submitted.state->feedback) return select(submitted);
    paintersSort_ = submitted.methods.hiddenSurface == HiddenSurface::PaintersSort;
    if (BatchSetup::handles(submitted)) {
        setup_.setUp(submitted, tiles_, stats_);
        return;
    }
    const Batch batch = setup_.stage(submitted);
    if (isTriangleMode(batch.mode)) {
        drawUnfilled(batch);
    } else {
        drawPointsAndLines(batch.mode, batch.vertices, *batch.state, stippler_, framebuffer_, tiles_);
    }
}

void BatchDrawer::draw(BatchChunk& chunk) {
    if (!chunk.setUp) {
        lightChunk(chunk);
        for (const BatchEntry& entry : chunk.batches) {
            keepTexture(entry.state->texture);
            draw(chunk.batch(entry));
        }
        return;
    }
    for (const BatchEntry& entry : chunk.batches) keepTexture(entry.state->texture);
    tiles_.queue(chunk.setUpTriangles);
    stats_ = stats_ + chunk.setupStats;
    paintersSort_ = chunk.batches.back().methods.hiddenSurface == HiddenSurface::PaintersSort;
}

// The reference's selection and feedback run its draw module's clip and cull stages and record
// what comes out (selection: the window depths; feedback: the primitives); in selection
// polygons count as filled whatever their polygon mode.
void BatchDrawer::select(const SubmittedBatch& submitted) {
    FeedbackOutput feedback(feedback_, feedbackLineReset_, framebuffer_.height());
    FeedbackOutput* output = submitted.state->feedback ? &feedback : nullptr;
    if (output && isTriangleMode(submitted.mode) && !BatchSetup::filled(*submitted.state))
        return feedbackUnfilled(submitted, feedback);
    if (isTriangleMode(submitted.mode)) return setup_.select(submitted, hits_, output, stats_);
    selectPointsAndLines(submitted.mode, setup_.stage(submitted).vertices, *submitted.state, framebuffer_.height(),
                         hits_, output);
}

// Feedback of polygons in line or point mode: the unfilled stage's lines and points (and the
// triangles of a face still filled) go to the feedback. With flat shading the draw module's
// flatshade stage, in its pipeline with the unfilled stage, colours a filled one too.
void BatchDrawer::feedbackUnfilled(const SubmittedBatch& submitted, FeedbackOutput& feedback) {
    const Batch batch = setup_.stage(submitted);
    const bool flat = batch.state->shadeModel == ShadeModel::Flat;
    const UnfilledTarget target{[&](WindowVertex v0, WindowVertex v1, WindowVertex v2, const glm::vec4& flatColor) {
                                    if (flat) v0.color = v1.color = v2.color = flatColor;
                                    feedback.triangle(v0, v1, v2);
                                },
                                nullptr, &feedback};
    drawUnfilledBatch(batch.mode, batch.vertices, setup_.outcodes(), setup_.windowVertices(),
                      ViewportTransform(*batch.state, framebuffer_.height()), *batch.state, anyEdgeShown(batch),
                      framebuffer_, stats_, target);
}

void BatchDrawer::drawUnfilled(const Batch& batch) {
    const UnfilledTarget target{
        [&](const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const glm::vec4& flatColor) {
            setup_.setUpTriangle(batch, v0, v1, v2, flatColor, tiles_, stats_);
        },
        &tiles_, nullptr, &stippler_};
    drawUnfilledBatch(batch.mode, batch.vertices, setup_.outcodes(), setup_.windowVertices(),
                      ViewportTransform(*batch.state, framebuffer_.height()), *batch.state, anyEdgeShown(batch),
                      framebuffer_, stats_, target);
}

}  // namespace glrenderer
