// Deferred, tiled, multi-threaded rasterization must give the same bits as drawing each
// triangle on its own, whatever the order tiles are processed in.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "pipeline_fixture.h"

using glrenderer::PrimitiveMode;
using testing_support::PipelineFixture;

TEST(TileRasterizer, QueuedFrameEqualsTriangleByTriangle) {
    constexpr int kWidth = 300, kHeight = 200, kTriangles = 2000;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> x(-40.0f, kWidth + 40.0f), y(-40.0f, kHeight + 40.0f), z(-0.9f, 0.9f),
        c(0.0f, 1.0f);
    PipelineFixture queued(kWidth, kHeight), oneByOne(kWidth, kHeight);
    for (PipelineFixture* f : {&queued, &oneByOne}) {
        f->state.depthTest = true;
        f->pipeline.clear(true, 0, true, 0xFFFFFF);
    }
    std::vector<glrenderer::Vertex> all;
    for (int i = 0; i < 3 * kTriangles; ++i)
        all.push_back(queued.windowVertex(x(random), y(random), z(random), {c(random), c(random), c(random), 1}));
    queued.draw(PrimitiveMode::Triangles, all);
    for (int i = 0; i < kTriangles; ++i)
        oneByOne.draw(PrimitiveMode::Triangles, {all.begin() + 3 * i, all.begin() + 3 * i + 3});
    EXPECT_TRUE(std::equal(queued.framebuffer.color().begin(), queued.framebuffer.color().end(),
                           oneByOne.framebuffer.color().begin()));
    EXPECT_TRUE(std::equal(queued.framebuffer.depth().begin(), queued.framebuffer.depth().end(),
                           oneByOne.framebuffer.depth().begin()));
    EXPECT_EQ(queued.pipeline.stats().fragments, oneByOne.pipeline.stats().fragments);
    EXPECT_EQ(queued.pipeline.stats().fragmentsPassed, oneByOne.pipeline.stats().fragmentsPassed);
    EXPECT_GT(queued.pipeline.stats().fragmentsPassed, 0u);
}

namespace {

constexpr std::uint32_t kRed = 0xFF0000FFu, kGreen = 0xFF00FF00u, kBlue = 0xFFFF0000u;

// Every pixel has `rgba` and every depth `depth24`.
bool holdsEverywhere(const PipelineFixture& f, std::uint32_t rgba, std::uint32_t depth24) {
    return std::all_of(f.framebuffer.color().begin(), f.framebuffer.color().end(),
                       [&](std::uint32_t c) { return c == rgba; }) &&
           std::all_of(f.framebuffer.depth().begin(), f.framebuffer.depth().end(),
                       [&](std::uint32_t d) { return d == depth24; });
}

void clearAndFinish(PipelineFixture& f, std::uint32_t rgba, std::uint32_t depth24) {
    f.pipeline.clear(true, rgba, true, depth24);
    f.pipeline.finish();
}

}  // namespace

// Tiles that still hold a clear's values are not written again by the next clear; whatever
// drew in between (triangles, lines drawn at once, another clear value, writes from outside
// the pipeline, a new buffer) must still be cleared away.
TEST(TileRasterizer, ClearingAgainClearsWhateverWasDrawnSince) {
    PipelineFixture f(200, 150);  // several tiles
    f.state.depthTest = true;
    clearAndFinish(f, kRed, 0xFFFFFF);
    ASSERT_TRUE(holdsEverywhere(f, kRed, 0xFFFFFF));

    f.draw(PrimitiveMode::Triangles,
           {f.windowVertex(10, 10, 0.2f), f.windowVertex(190, 20, 0.2f), f.windowVertex(100, 140, 0.2f)});
    ASSERT_FALSE(holdsEverywhere(f, kRed, 0xFFFFFF));
    clearAndFinish(f, kRed, 0xFFFFFF);
    EXPECT_TRUE(holdsEverywhere(f, kRed, 0xFFFFFF)) << "after triangles";

    f.draw(PrimitiveMode::Lines, {f.windowVertex(5.5f, 5.5f, -0.5f), f.windowVertex(195.5f, 140.5f, -0.5f)});
    ASSERT_FALSE(holdsEverywhere(f, kRed, 0xFFFFFF));
    clearAndFinish(f, kRed, 0xFFFFFF);
    EXPECT_TRUE(holdsEverywhere(f, kRed, 0xFFFFFF)) << "after lines";

    clearAndFinish(f, kGreen, 0x123456);
    EXPECT_TRUE(holdsEverywhere(f, kGreen, 0x123456)) << "another clear value";
    clearAndFinish(f, kGreen, 0x123456);

    f.framebuffer.color()[4321] = kBlue;
    f.framebuffer.depth()[4321] = 7;
    f.framebuffer.markWritten();
    clearAndFinish(f, kGreen, 0x123456);
    EXPECT_TRUE(holdsEverywhere(f, kGreen, 0x123456)) << "after a write from outside";

    f.framebuffer.resize(200, 150);  // same size, new zeroed buffers
    clearAndFinish(f, kGreen, 0x123456);
    EXPECT_TRUE(holdsEverywhere(f, kGreen, 0x123456)) << "after a resize";

    // Clears in a row, nothing drawn between them, are carried out as one.
    f.pipeline.clear(true, kRed, true, 0x111111);
    f.pipeline.clear(true, kBlue, false, 0);
    f.pipeline.finish();
    EXPECT_TRUE(holdsEverywhere(f, kBlue, 0x111111)) << "clears in a row";
}
