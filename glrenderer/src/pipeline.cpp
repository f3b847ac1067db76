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
           batch.state.polygonBack == PolygonMode::Fill && batch.vertices.size() >= Pipeline::kPartVertices;
}

}  // namespace

Pipeline::Pipeline(Framebuffer& framebuffer)
    : batch_(std::make_unique<Batch>()), drawer_(std::make_unique<BatchDrawer>(framebuffer, stats_)) {
    if (workerThreadCount() > 1) thread_ = std::make_unique<BatchThread>(*drawer_);
}

Pipeline::~Pipeline() = default;

bool Pipeline::takesParts(PrimitiveMode mode) { return isMergeable(mode); }

void Pipeline::submit(const DrawState& state, PrimitiveMode mode, std::span<const Vertex> vertices) {
    ++stats_.primitivesByMode[static_cast<std::size_t>(mode)];
    append(state, mode, vertices);
    if (!isMergeable(mode)) endBatch();
}

void Pipeline::submitPart(const DrawState& state, PrimitiveMode mode, std::span<const Vertex> vertices) {
    append(state, mode, vertices);
}

void Pipeline::append(const DrawState& state, PrimitiveMode mode, std::span<const Vertex> vertices) {
    stats_.vertices += vertices.size();
    const std::size_t usable = usableVertexCount(mode, vertices.size());
    if (usable == 0) return;
    Batch& batch = *batch_;
    if (!batch.vertices.empty() &&
        (mode != batch.mode || !isMergeable(mode) || !(state == batch.state))) {
        endBatch();
    }
    batch.state = state;
    batch.methods = methods_;
    batch.mode = mode;
    batch.vertices.insert(batch.vertices.end(), vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(usable));
    if (canCut(batch)) endBatch();
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
