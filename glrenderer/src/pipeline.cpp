#include "glrenderer/pipeline.h"

#include "batch.h"
#include "batch_drawer.h"
#include "batch_thread.h"
#include "decompose.h"
#include "thread_count.h"

namespace glrenderer {
namespace {

// Modes whose consecutive glBegin/glEnd blocks the reference merges into one draw.
bool isMergeable(PrimitiveMode mode) {
    return mode == PrimitiveMode::Points || mode == PrimitiveMode::Lines ||
           mode == PrimitiveMode::Triangles || mode == PrimitiveMode::Quads;
}

// Filled independent triangles come out the same however a batch of them is cut, so a long
// batch is drawn in parts while the program goes on. (Quads are not: the batch as a whole
// decides their diagonal.)
bool canCut(const Batch& batch) {
    return batch.mode == PrimitiveMode::Triangles && batch.state.polygonFront == PolygonMode::Fill &&
           batch.state.polygonBack == PolygonMode::Fill;
}

}  // namespace

Pipeline::Pipeline(Framebuffer& framebuffer)
    : batch_(std::make_unique<Batch>()), drawer_(std::make_unique<BatchDrawer>(framebuffer, stats_)) {
    if (workerThreadCount() > 1) thread_ = std::make_unique<BatchThread>(*drawer_);
}

Pipeline::~Pipeline() = default;

void Pipeline::beginPrimitive(const DrawState& state, PrimitiveMode mode) {
    Batch& batch = *batch_;
    if (!batch.vertices.empty() && (mode != batch.mode || !isMergeable(mode) || !(state == batch.state))) {
        endBatch();
    }
    batch.state = state;
    batch.methods = methods_;
    batch.mode = mode;
    cuttable_ = canCut(batch);
    open_.clear();
}

void Pipeline::handOverPart() {
    stats_.vertices += open_.size();
    batch_->vertices.insert(batch_->vertices.end(), open_.begin(), open_.end());
    open_.clear();
    endBatch();
}

void Pipeline::endPrimitive() {
    Batch& batch = *batch_;
    const std::size_t count = open_.size();
    stats_.vertices += count;
    ++stats_.primitivesByMode[static_cast<std::size_t>(batch.mode)];
    const std::size_t usable = usableVertexCount(batch.mode, count);
    batch.vertices.insert(batch.vertices.end(), open_.begin(), open_.begin() + static_cast<std::ptrdiff_t>(usable));
    open_.clear();
    cuttable_ = false;
    // The reference keeps an incomplete tail's vertices in its buffer, so the next block is not
    // contiguous and is not merged: dropping vertices ends the batch (measured with OSMesa).
    const bool droppedVertices = usable < count;
    if (!isMergeable(batch.mode) || droppedVertices || (canCut(batch) && batch.vertices.size() >= kPartVertices)) {
        endBatch();
    }
}

void Pipeline::submit(const DrawState& state, PrimitiveMode mode, std::span<const Vertex> vertices) {
    beginPrimitive(state, mode);
    for (const Vertex& vertex : vertices) addVertex() = vertex;
    endPrimitive();
}

void Pipeline::endBatch() {
    if (batch_->vertices.empty()) return;
    if (thread_) {
        thread_->post(*batch_);
    } else {
        drawer_->draw(*batch_);
        batch_->vertices.clear();
    }
}

void Pipeline::finish() {
    endBatch();
    if (thread_) thread_->wait();
    drawer_->flush();
}

void Pipeline::resetStats() {
    if (thread_) thread_->wait();  // counts of batches still being drawn belong to the old frame
    stats_ = {};
}

void Pipeline::clear(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24) {
    finish();
    drawer_->clearAtFlush(color, rgba, depth, depth24);
}

}  // namespace glrenderer
