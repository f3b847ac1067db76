#pragma once
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

#include "batch.h"
#include "batch_drawer.h"

namespace glrenderer {

// Draws batches on a thread of its own, in the order they were posted, so that the program's
// gl* calls overlap the pipeline's per-batch work (llvmpipe likewise sets up while the program
// goes on). Vertex arrays travel back to the poster for reuse: steady state allocates nothing.
class BatchThread {
public:
    explicit BatchThread(BatchDrawer& drawer);
    ~BatchThread();
    BatchThread(const BatchThread&) = delete;
    BatchThread& operator=(const BatchThread&) = delete;

    // Queues `batch`; its vertices are taken and replaced by an empty array from an earlier batch.
    void post(Batch& batch);
    // Returns when every posted batch has been drawn; if the thread sleeps, the caller draws
    // what is left itself.
    void wait();

private:
    // The thread is woken only once this many vertices (or kMaxPostedBatches batches) wait, or
    // on wait(): a wake-up costs tens of microseconds on a virtual machine, and small batches
    // come by the thousand.
    static constexpr std::size_t kWakeVertices = 2048;
    // A program that outruns the thread waits once this many batches are queued: it bounds the
    // memory in flight, and the vertex arrays in circulation stop growing after the first frame.
    static constexpr std::size_t kMaxPostedBatches = 64;

    void run();
    bool hasWork() const;
    // Draws everything posted so far with the lock released; called with it held.
    void drawPosted(std::unique_lock<std::mutex>& lock);

    BatchDrawer& drawer_;
    std::mutex mutex_;
    std::condition_variable wake_, idle_, room_;
    std::vector<Batch> posted_;
    std::vector<Batch> inHand_;  // being drawn, by the thread or by wait()'s caller
    std::vector<std::vector<Vertex>> spareVertices_;
    std::size_t postedVertices_ = 0;
    bool drawing_ = false;  // inHand_ is being drawn
    bool waited_ = false;  // someone is in wait(): draw whatever is posted
    bool stopping_ = false;
    std::thread thread_;  // last: starts once the members above exist
};

}  // namespace glrenderer
