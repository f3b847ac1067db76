// A frame in steady state allocates nothing: every buffer the pipeline needs (vertex batches,
// queued triangles, tile bins, jobs for the worker threads) is kept from the frames before.
// Counted by replacing the global operator new in this test binary.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/context.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "scene.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// With inlining, GCC 12 sees std::free after a replaced operator new and reports a mismatch that
// is not one: this operator new allocates with std::malloc.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

class SteadyStateAllocations : public testing::TestWithParam<const char*> {};

TEST_P(SteadyStateAllocations, AFrameAllocatesNothing) {
    const scenes::Scene* scene = scenes::findScene(GetParam());
    ASSERT_NE(scene, nullptr);
    constexpr int kWidth = 320, kHeight = 240;
    mygl::Context context(kWidth, kHeight);
    context.makeCurrent();
    for (int frame = 0; frame < 4; ++frame) {  // warm-up: buffers grow to the scene's needs
        scene->draw(kWidth, kHeight, 0);
        glFinish();
    }
    const long before = allocations.load();
    for (int frame = 0; frame < 3; ++frame) {
        scene->draw(kWidth, kHeight, 0);
        glFinish();
    }
    EXPECT_EQ(allocations.load() - before, 0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(BenchAndCourseScenes, SteadyStateAllocations,
                         testing::Values("bench-torus", "bench-fill", "bench-cubes", "bench-tiny", "bench-gears",
                                         "bench-gears-lists", "bench-mesh", "bench-lit-torus", "bench-fog-terrain",
                                         "bench-textured-cubes", "bench-fog-textured-terrain", "course-f4",
                                         "near-plane", "wireframe-cube", "lines-points"),
                         [](const testing::TestParamInfo<const char*>& param) {
                             std::string name = param.param;
                             for (char& c : name) c = c == '-' ? '_' : c;
                             return name;
                         });
