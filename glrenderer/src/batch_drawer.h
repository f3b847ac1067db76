#pragma once
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "batch.h"
#include "batch_setup.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/hit_range.h"
#include "glrenderer/stats.h"
#include "tile_rasterizer.h"

namespace glrenderer {

// The pipeline's per-batch work on the batch thread: triangles set up (BatchSetup) and binned
// for the tile rasterizer, points and lines drawn at once.
class BatchDrawer {
public:
    explicit BatchDrawer(Framebuffer& framebuffer);

    Framebuffer& framebuffer() { return framebuffer_; }
    // What it counted (triangles and fragments) since the last reset.
    const Stats& stats() const { return stats_; }
    void resetStats() { stats_ = {}; }

    void draw(const SubmittedBatch& batch);
    // What GL_SELECT batches hit since the last call.
    HitRange takeHits() { return std::exchange(hits_, {}); }
    FeedbackPrimitives takeFeedback() { return std::exchange(feedback_, {}); }
    // Every batch of the chunk, in order; triangles its poster has set up already are only
    // queued.
    void draw(BatchChunk& chunk);
    // Rasterizes the binned triangles (in parallel tiles) and any pending clear.
    void flush();
    // The same if triangles are queued; a pending clear alone stays pending.
    void flushTriangles() {
        if (tiles_.queued() > 0) flush();
    }
    // Where chunks' triangles are set up ahead (BatchSetup::setUp(BatchChunk&, ...)).
    TriangleArena& triangleArena() { return tiles_.arena(); }
    // Once nothing is queued and every other writer of the arena is released.
    void releaseTriangles() { tiles_.releaseTriangles(); }
    // Whether enough is queued for drawSomeTiles() to be worth it (never under the painter's
    // sort, which orders a tile's whole queue).
    bool worthDrawingTilesEarly() const { return !paintersSort_ && tiles_.queued() >= kEarlyTriangles; }
    // Draws queued tiles on the calling thread until stop() returns true: a thread that would
    // otherwise wait for the program does part of what flush() would do.
    template <class Stop>
    void drawSomeTiles(Stop&& stop) {
        tiles_.drawSomeTiles(stats_, stop);
    }
    // Clears the framebuffer at the next flush(), tile by tile.
    void clearAtFlush(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24) {
        tiles_.clearAtFlush(color, rgba, depth, depth24);
    }

private:
    static constexpr std::size_t kEarlyTriangles = 2048;

    void drawUnfilled(const Batch& batch);
    void select(const SubmittedBatch& batch);
    void feedbackUnfilled(const SubmittedBatch& batch, FeedbackOutput& feedback);

    static constexpr std::size_t kTexturesReserved = 64;

    // Keeps the texture the chunk's batch reads alive until its triangles are drawn (flush).
    void keepTexture(const TextureState& texture);

    Framebuffer& framebuffer_;
    // Written for every triangle on the batch thread: a line of its own, not shared with
    // anything the program's thread writes.
    alignas(64) Stats stats_;
    TileRasterizer tiles_;
    BatchSetup setup_;
    bool paintersSort_ = false;  // of the last batch drawn: how its tiles order triangles
    HitRange hits_;
    FeedbackPrimitives feedback_;
    bool feedbackLineReset_ = false;
    // The textures queued triangles read, released when the tiles are drawn.
    std::vector<std::shared_ptr<const Texture>> texturesInUse_;
};

}  // namespace glrenderer
