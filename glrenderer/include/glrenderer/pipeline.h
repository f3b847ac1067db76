#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/methods.h"
#include "glrenderer/stats.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

class BatchDrawer;
class BatchThread;
struct Batch;

// Turns primitives in clip space into pixels of a Framebuffer.
//
// Consecutive submissions of the same mergeable mode (points, lines, triangles, quads) form one
// batch until endBatch(), as the reference's vertex buffer merges glBegin/glEnd blocks: whether
// any vertex of the batch needs clipping decides how quads are split, so the batch matters.
// Batches are drawn on a thread of the pipeline's own while the caller goes on, and triangles
// are queued and rasterized in screen tiles by worker threads: pixels and counters are only
// promised after finish(). Call finish() before resizing the framebuffer.
class Pipeline {
public:
    explicit Pipeline(Framebuffer& framebuffer);
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    // A primitive (a glBegin/glEnd block): begun, given its vertices one by one, ended. The
    // vertices go straight into the batch; a long primitive of independent filled triangles is
    // handed to the batch thread in parts of kPartVertices while the program goes on.
    static constexpr std::size_t kPartVertices = 3072;
    void beginPrimitive(const DrawState& state, PrimitiveMode mode);
    void addVertex(const Vertex& vertex) {
        openVertices_.push_back(vertex);
        if (openVertices_.size() == nextCut_) cutOpenPrimitive();
    }
    void endPrimitive();
    // All three for a whole primitive.
    void submit(const DrawState& state, PrimitiveMode mode, std::span<const Vertex> vertices);

    void endBatch();
    void finish();

    // Clears with colors/depth already converted by the caller's rules (see color_convert.h).
    void clear(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24);

    // Takes effect for primitives submitted after the call.
    void setMethods(const Methods& methods) {
        endBatch();
        methods_ = methods;
    }
    const Methods& methods() const { return methods_; }

    // Complete after finish().
    const Stats& stats() const { return stats_; }
    void resetStats();

private:
    void cutOpenPrimitive();

    Stats stats_;
    Methods methods_;
    std::unique_ptr<Batch> batch_;  // being merged on the caller's thread
    std::vector<Vertex>& openVertices_;  // batch_->vertices
    std::size_t primitiveStart_ = 0;  // where the open primitive's vertices begin
    std::size_t nextCut_ = 0;  // the batch size at which the open primitive is cut, if ever
    std::unique_ptr<BatchDrawer> drawer_;
    std::unique_ptr<BatchThread> thread_;  // null when the pipeline runs on one thread
};

}  // namespace glrenderer
