#pragma once
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

struct TriangleIndices;
struct WindowVertex;
class ViewportTransform;
class TileRasterizer;

// Turns primitives in clip space into pixels of a Framebuffer.
//
// Consecutive submissions of the same mergeable mode (points, lines, triangles, quads) form one
// batch until endBatch(), as the reference's vertex buffer merges glBegin/glEnd blocks: whether
// any vertex of the batch needs clipping decides how quads are split, so the batch matters.
// Pixels are only promised after finish(): triangles are queued and drawn in screen tiles by
// worker threads. Call finish() before resizing the framebuffer.
class Pipeline {
public:
    explicit Pipeline(Framebuffer& framebuffer);
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

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

    const Stats& stats() const { return stats_; }
    void resetStats() { stats_ = {}; }

private:
    void drawBatch();
    void flushTiles();
    void drawTriangle(const TriangleIndices& triangle, const ViewportTransform& viewport);
    void setupTriangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                       const glm::vec4& flatColor);

    Framebuffer& framebuffer_;
    Stats stats_;
    Methods methods_;
    DrawState batchState_;
    PrimitiveMode batchMode_ = PrimitiveMode::Points;
    std::vector<Vertex> batch_;
    // Per batch vertex: which clip planes it is outside of, and its window position.
    std::vector<std::uint8_t> outcodes_;
    std::vector<WindowVertex> windowVertices_;
    std::unique_ptr<TileRasterizer> tiles_;
};

}  // namespace glrenderer
