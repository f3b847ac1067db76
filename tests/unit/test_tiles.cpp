// Deferred, tiled, multi-threaded rasterization must give the same bits as drawing each
// triangle on its own, whatever the order tiles are processed in.
#include <gtest/gtest.h>

#include <random>

#include "pipeline_fixture.h"

using glrenderer::PrimitiveMode;
using testing_support::PipelineFixture;

TEST(TileRasterizer, QueuedFrameEqualsTriangleByTriangle) {
    constexpr int kWidth = 300, kHeight = 200, kTriangles = 2000;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> x(-40.0f, kWidth + 40.0f), y(-40.0f, kHeight + 40.0f),
        z(-0.9f, 0.9f), c(0.0f, 1.0f);
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
