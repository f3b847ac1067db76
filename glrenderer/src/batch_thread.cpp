#include "batch_thread.h"

#include "denormals_are_zero.h"

namespace glrenderer {

BatchThread::BatchThread(BatchDrawer& drawer, const Framebuffer& framebuffer,
                         std::vector<std::unique_ptr<BatchChunk>> chunks)
    : drawer_(drawer), setup_(framebuffer, kChunkVertices), writer_(drawer.triangleArena()), free_(std::move(chunks)) {
    posted_.reserve(free_.size() + 1);
    free_.reserve(free_.size() + 1);
    thread_ = std::thread([this] { run(); });
}

BatchThread::~BatchThread() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        needed_.store(true, std::memory_order_relaxed);  // cut a tile pass short
    }
    wake_.notify_one();
    thread_.join();
}

std::unique_ptr<BatchChunk> BatchThread::post(std::unique_ptr<BatchChunk> chunk) {
    std::unique_lock lock(mutex_);
    if (free_.empty()) {  // the thread is behind: rather than wait, take some of its work
        lock.unlock();
        setup_.setUp(*chunk, writer_);
        lock.lock();
    }
    posted_.push_back(std::move(chunk));
    needed_.store(true, std::memory_order_relaxed);
    wake_.notify_one();
    room_.wait(lock, [this] { return !free_.empty(); });
    std::unique_ptr<BatchChunk> empty = std::move(free_.back());
    free_.pop_back();
    return empty;
}

void BatchThread::wait() {
    std::unique_lock lock(mutex_);
    if (!drawing_) {
        drawPosted(lock, false);
        return;
    }
    waiting_ = true;
    needed_.store(true, std::memory_order_relaxed);
    setUpQueued(lock);
    idle_.wait(lock, [this] { return posted_.empty() && !drawing_; });
    waiting_ = false;
}

void BatchThread::setUpQueued(std::unique_lock<std::mutex>& lock) {
    // Counted from the back: the thread only removes chunks from the front, and waits for the
    // one being set up here if it gets to it.
    for (std::size_t fromBack = 0; drawing_ && fromBack < posted_.size(); ++fromBack) {
        BatchChunk& chunk = *posted_[posted_.size() - 1 - fromBack];
        if (chunk.setUp) continue;
        settingUp_ = &chunk;
        lock.unlock();
        setup_.setUp(chunk, writer_);
        lock.lock();
        settingUp_ = nullptr;
        setUp_.notify_one();
    }
}

void BatchThread::drawPosted(std::unique_lock<std::mutex>& lock, bool tilesWhenIdle) {
    drawing_ = true;
    for (;;) {
        while (!posted_.empty()) {
            std::unique_ptr<BatchChunk> chunk = std::move(posted_.front());
            posted_.erase(posted_.begin());
            setUp_.wait(lock, [&] { return settingUp_ != chunk.get(); });
            lock.unlock();
            drawer_.draw(*chunk);
            chunk->clear();
            lock.lock();
            free_.push_back(std::move(chunk));
            room_.notify_one();
        }
        if (!tilesWhenIdle || waiting_ || stopping_ || !drawer_.worthDrawingTilesEarly()) break;
        needed_.store(false, std::memory_order_relaxed);
        lock.unlock();
        drawer_.drawSomeTiles([this] { return needed_.load(std::memory_order_relaxed); });
        lock.lock();
    }
    drawing_ = false;
}

void BatchThread::run() {
    const DenormalsAreZero denormals;
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || (!posted_.empty() && !drawing_); });
        if (stopping_) return;
        drawPosted(lock, true);
        idle_.notify_all();
    }
}

}  // namespace glrenderer
