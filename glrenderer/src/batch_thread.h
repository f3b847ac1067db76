#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "batch.h"
#include "batch_drawer.h"
#include "batch_setup.h"

namespace glrenderer {

// Draws chunks of batches on a thread of its own, in the order they were posted, so that the
// program's gl* calls overlap the pipeline's per-batch work (llvmpipe likewise sets up while
// the program goes on). A fixed set of chunks circulates between the poster and the thread, so
// steady state allocates nothing and the memory in flight is bounded.
//
// When the thread is behind, the poster does not just wait: it sets up the triangles of chunks
// still queued (BatchSetup, which needs no order), and the thread only bins them, in order.
class BatchThread {
public:
    // `chunks` are kept for post() to hand out, the most recently drawn first (its memory is
    // the most likely to be in cache).
    BatchThread(BatchDrawer& drawer, const Framebuffer& framebuffer, std::vector<std::unique_ptr<BatchChunk>> chunks);
    ~BatchThread();
    BatchThread(const BatchThread&) = delete;
    BatchThread& operator=(const BatchThread&) = delete;

    // Queues `chunk` for drawing and returns an empty one to fill. If all are in use, it sets
    // the chunk's triangles up first, then waits if it must.
    std::unique_ptr<BatchChunk> post(std::unique_ptr<BatchChunk> chunk);
    // Returns when every posted chunk has been drawn, setting up queued chunks from the last
    // while the thread draws the first; if the thread sleeps, the caller draws what is left
    // itself (waking the thread takes longer than a small frame's batches on a virtual machine).
    void wait();
    // After wait() and the tiles' flush: the triangles set up here are no longer needed.
    void releaseTriangles() { writer_.release(); }

private:
    void run();
    // Draws the posted chunks in order, with the lock released while drawing; called with it
    // held. With tilesWhenIdle, once nothing is posted it goes on to draw queued tiles until a
    // chunk is posted or someone waits.
    void drawPosted(std::unique_lock<std::mutex>& lock, bool tilesWhenIdle);
    // In wait(): sets up queued chunks, last first, while the thread is drawing.
    void setUpQueued(std::unique_lock<std::mutex>& lock);

    BatchDrawer& drawer_;
    BatchSetup setup_;    // the poster's
    ArenaWriter writer_;  // the poster's, into the drawer's triangle arena
    std::mutex mutex_;
    std::condition_variable wake_, idle_, room_, setUp_;
    // Drawn first in, first out (a handful: erasing at the front is cheap and allocates nothing);
    // free ones reused last in, first out.
    std::vector<std::unique_ptr<BatchChunk>> posted_, free_;
    bool drawing_ = false;  // the drawer is in use, by the thread or by wait()'s caller
    // What a thread about to wait spins on first (spinUntil): copies of the state above, and a
    // count of posts.
    static constexpr std::chrono::microseconds kSpinBudget{100};
    std::atomic<bool> busy_{false};  // drawPosted() runs
    std::atomic<std::size_t> freeChunks_{0}, posts_{0};
    std::atomic<bool> waiting_{false};  // someone is in wait()
    bool stopping_ = false;
    const BatchChunk* settingUp_ = nullptr;  // queued, being set up by wait()'s caller
    std::atomic<bool> needed_{false};        // a chunk was posted or someone waits: stop drawing tiles
    std::thread thread_;                     // last: starts once the members above exist
};

}  // namespace glrenderer
