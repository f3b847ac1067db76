#include "batch_thread.h"

#include <immintrin.h>

#include "denormals_are_zero.h"
#include "spin_wait.h"

namespace glrenderer {

BatchThread::BatchThread(BatchDrawer& drawer, const Framebuffer& framebuffer,
                         std::vector<std::unique_ptr<BatchChunk>> chunks)
    : drawer_(drawer), setup_(framebuffer, kChunkVertices), writer_(drawer.triangleArena()), free_(std::move(chunks)) {
    posted_.reserve(free_.size() + 1);
    free_.reserve(free_.size() + 1);
    freeChunks_.store(free_.size(), std::memory_order_relaxed);
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
    _mm_sfence();  // the vertices were written with streaming stores
    std::unique_lock lock(mutex_);
    if (free_.empty()) {  // the thread is behind: rather than wait, take some of its work
        lock.unlock();
        setup_.setUp(*chunk, writer_);
        lock.lock();
    }
    posted_.push_back(std::move(chunk));
    posts_.fetch_add(1, std::memory_order_release);
    needed_.store(true, std::memory_order_relaxed);
    wake_.notify_one();
    if (free_.empty()) {
        lock.unlock();
        spinUntil([this] { return freeChunks_.load(std::memory_order_acquire) > 0; }, kSpinBudget);
        lock.lock();
    }
    room_.wait(lock, [this] { return !free_.empty(); });
    std::unique_ptr<BatchChunk> empty = std::move(free_.back());
    free_.pop_back();
    freeChunks_.store(free_.size(), std::memory_order_relaxed);
    return empty;
}

void BatchThread::wait() {
    std::unique_lock lock(mutex_);
    if (!drawing_) {
        drawPosted(lock, false);
        return;
    }
    waiting_.store(true, std::memory_order_relaxed);
    needed_.store(true, std::memory_order_relaxed);
    setUpQueued(lock);
    if (!posted_.empty() || drawing_) {
        lock.unlock();
        spinUntil([this] { return !busy_.load(std::memory_order_acquire); }, kSpinBudget);
        lock.lock();
    }
    idle_.wait(lock, [this] { return posted_.empty() && !drawing_; });
    waiting_.store(false, std::memory_order_relaxed);
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
    busy_.store(true, std::memory_order_relaxed);
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
            freeChunks_.store(free_.size(), std::memory_order_release);
            room_.notify_one();
        }
        if (!tilesWhenIdle || waiting_ || stopping_ || !drawer_.worthDrawingTilesEarly()) break;
        needed_.store(false, std::memory_order_relaxed);
        lock.unlock();
        drawer_.drawSomeTiles([this] { return needed_.load(std::memory_order_relaxed); });
        lock.lock();
    }
    drawing_ = false;
    busy_.store(false, std::memory_order_release);
}

void BatchThread::run() {
    const DenormalsAreZero denormals;
    std::unique_lock lock(mutex_);
    for (;;) {
        // Between chunks of a frame, spin a while first (not while the frame ends: the tiles'
        // threads need the cores then).
        if (posted_.empty() && !stopping_ && !waiting_.load(std::memory_order_relaxed)) {
            const std::size_t seen = posts_.load(std::memory_order_relaxed);
            lock.unlock();
            spinUntil(
                [&] {
                    return posts_.load(std::memory_order_acquire) != seen || waiting_.load(std::memory_order_relaxed);
                },
                kSpinBudget);
            lock.lock();
        }
        wake_.wait(lock, [this] { return stopping_ || (!posted_.empty() && !drawing_); });
        if (stopping_) return;
        drawPosted(lock, true);
        idle_.notify_all();
    }
}

}  // namespace glrenderer
