#include "batch_thread.h"

namespace glrenderer {

BatchThread::BatchThread(BatchDrawer& drawer, std::vector<std::unique_ptr<BatchChunk>> chunks)
    : drawer_(drawer), free_(std::move(chunks)) {
    posted_.reserve(free_.size() + 1);
    free_.reserve(free_.size() + 1);
    thread_ = std::thread([this] { run(); });
}

BatchThread::~BatchThread() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

std::unique_ptr<BatchChunk> BatchThread::post(std::unique_ptr<BatchChunk> chunk) {
    std::unique_lock lock(mutex_);
    posted_.push_back(std::move(chunk));
    wake_.notify_one();
    room_.wait(lock, [this] { return !free_.empty(); });
    std::unique_ptr<BatchChunk> empty = std::move(free_.back());
    free_.pop_back();
    return empty;
}

void BatchThread::wait() {
    std::unique_lock lock(mutex_);
    if (!drawing_) {
        drawPosted(lock);
        return;
    }
    idle_.wait(lock, [this] { return posted_.empty() && !drawing_; });
}

void BatchThread::drawPosted(std::unique_lock<std::mutex>& lock) {
    drawing_ = true;
    while (!posted_.empty()) {
        std::unique_ptr<BatchChunk> chunk = std::move(posted_.front());
        posted_.erase(posted_.begin());
        lock.unlock();
        for (const BatchEntry& entry : chunk->batches) drawer_.draw(chunk->batch(entry));
        chunk->clear();
        lock.lock();
        free_.push_back(std::move(chunk));
        room_.notify_one();
    }
    drawing_ = false;
}

void BatchThread::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || (!posted_.empty() && !drawing_); });
        if (stopping_) return;
        drawPosted(lock);
        idle_.notify_all();
    }
}

}  // namespace glrenderer
