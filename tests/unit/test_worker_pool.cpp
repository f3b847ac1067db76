// The worker pool runs every index of a job exactly once, whatever the number of threads and
// whichever end each thread takes its indices from.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "worker_pool.h"

using namespace glrenderer;

TEST(WorkerPool, RunsEveryIndexExactlyOnce) {
    for (unsigned threads = 1; threads <= 4; ++threads) {
        WorkerPool pool(threads);
        for (std::size_t count : {0u, 1u, 2u, 3u, 7u, 64u, 513u}) {
            for (int repeat = 0; repeat < 20; ++repeat) {
                std::vector<std::atomic<int>> runs(count);
                std::atomic<bool> badThread{false};
                auto task = [&](std::size_t index, unsigned thread) {
                    runs[index].fetch_add(1);
                    if (thread >= pool.threadCount()) badThread = true;
                };
                pool.run(count, task);
                for (std::size_t i = 0; i < count; ++i) {
                    ASSERT_EQ(runs[i].load(), 1) << threads << " threads, " << count << " indices, index " << i;
                }
                EXPECT_FALSE(badThread);
            }
        }
    }
}
