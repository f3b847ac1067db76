#include "batch_thread.h"

namespace glrenderer {

BatchThread::BatchThread(BatchDrawer& drawer) : drawer_(drawer), thread_([this] { run(); }) {}

BatchThread::~BatchThread() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void BatchThread::post(Batch& batch) {
    std::unique_lock lock(mutex_);
    if (posted_.size() >= kMaxPostedBatches) {
        wake_.notify_one();
        room_.wait(lock, [this] { return posted_.size() < kMaxPostedBatches; });
    }
    postedVertices_ += batch.vertices.size();
    posted_.push_back({batch.state, batch.methods, batch.mode, std::move(batch.vertices)});
    batch.vertices.clear();  // a moved-from vector is valid but unspecified
    if (!spareVertices_.empty()) {
        batch.vertices = std::move(spareVertices_.back());
        spareVertices_.pop_back();
    }
    if (postedVertices_ >= kWakeVertices) wake_.notify_one();
}

void BatchThread::wait() {
    std::unique_lock lock(mutex_);
    if (!drawing_) {
        // The thread sleeps: waking it would cost more than drawing the rest here (a wake-up
        // takes far longer than a small frame's batches on a virtual machine).
        drawPosted(lock);
        return;
    }
    waited_ = true;
    wake_.notify_one();
    idle_.wait(lock, [this] { return posted_.empty() && !drawing_; });
    waited_ = false;
}

void BatchThread::drawPosted(std::unique_lock<std::mutex>& lock) {
    inHand_.swap(posted_);
    postedVertices_ = 0;
    drawing_ = true;
    room_.notify_one();
    lock.unlock();
    for (const Batch& batch : inHand_) drawer_.draw(batch);
    lock.lock();
    for (Batch& batch : inHand_) {
        batch.vertices.clear();
        spareVertices_.push_back(std::move(batch.vertices));
    }
    inHand_.clear();
    drawing_ = false;
}

bool BatchThread::hasWork() const {
    return !posted_.empty() &&
           (waited_ || postedVertices_ >= kWakeVertices || posted_.size() >= kMaxPostedBatches);
}

void BatchThread::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || hasWork(); });
        if (stopping_) return;
        drawPosted(lock);
        if (posted_.empty()) idle_.notify_all();
    }
}

}  // namespace glrenderer
