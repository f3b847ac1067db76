#include "worker_pool.h"

#include "denormals_are_zero.h"

namespace glrenderer {

WorkerPool::WorkerPool(unsigned threads) {
    for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

bool WorkerPool::take(unsigned thread, std::size_t& index) {
    std::uint64_t range = remaining_.load(std::memory_order_relaxed);
    for (;;) {
        const std::uint64_t front = range & 0xFFFFFFFFu, back = range >> 32;
        if (front >= back) return false;
        const bool fromFront = thread % 2 == 0;
        const std::uint64_t next = fromFront ? range + 1 : range - (std::uint64_t{1} << 32);
        if (remaining_.compare_exchange_weak(range, next, std::memory_order_relaxed)) {
            index = static_cast<std::size_t>(fromFront ? front : back - 1);
            return true;
        }
    }
}

void WorkerPool::drain(unsigned thread) {
    for (std::size_t i = 0; take(thread, i);) job_.invoke(job_.task, i, thread);
}

void WorkerPool::run(std::size_t count, Job job) {
    const DenormalsAreZero denormals;
    if (workers_.empty() || count <= 1) {
        for (std::size_t i = 0; i < count; ++i) job.invoke(job.task, i, 0);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        job_ = job;
        remaining_ = std::uint64_t{count} << 32;
        ++generation_;
    }
    wake_.notify_all();
    drain(0);
    // Waits only for workers that joined in: one still waking up (which can take longer than the
    // whole job on a virtual machine) finds the job gone and goes back to sleep.
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return busy_ == 0; });
    job_.task = nullptr;
}

void WorkerPool::workerLoop(unsigned thread) {
    const DenormalsAreZero denormals;
    unsigned seen = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        if (!job_.task) continue;  // that job is over already
        ++busy_;
        lock.unlock();
        drain(thread);
        lock.lock();
        if (--busy_ == 0) done_.notify_one();
    }
}

}  // namespace glrenderer
