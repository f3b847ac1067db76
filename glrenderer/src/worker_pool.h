#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace glrenderer {

// A fixed set of threads that run one job at a time: run(count, task) calls task(i) for every
// i in [0, count) on the workers and the calling thread, and returns when all are done.
class WorkerPool {
public:
    explicit WorkerPool(unsigned threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    unsigned threadCount() const { return static_cast<unsigned>(workers_.size()) + 1; }
    void run(std::size_t count, const std::function<void(std::size_t index, unsigned thread)>& task);

private:
    void workerLoop(unsigned thread);
    void drain(unsigned thread);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(std::size_t, unsigned)>* task_ = nullptr;
    std::size_t count_ = 0;
    std::atomic<std::size_t> next_{0};
    unsigned busy_ = 0;  // workers inside the current job
    unsigned generation_ = 0;
    bool stopping_ = false;
};

}  // namespace glrenderer
