// Batches drawn on the pipeline's own thread, and long primitives handed over in parts, give
// the same pixels, depths and counts as everything drawn at once on the caller's thread.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <vector>

#include "glrenderer/color_convert.h"
#include "pipeline_fixture.h"

using glrenderer::PrimitiveMode;
using glrenderer::Vertex;
using testing_support::PipelineFixture;

namespace {

// Many overlapping smooth triangles at random depths: their order decides every pixel.
std::vector<Vertex> randomTriangles(const PipelineFixture& f, std::size_t count) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> position(-4.0f, 36.0f), depth(-0.9f, 0.9f), unit(0.0f, 1.0f);
    std::vector<Vertex> vertices;
    for (std::size_t i = 0; i < count * 3; ++i) {
        vertices.push_back(f.windowVertex(position(random), position(random), depth(random),
                                          {unit(random), unit(random), unit(random), 1.0f}));
    }
    return vertices;
}

struct Drawn {
    std::vector<std::uint32_t> color, depth;
    glrenderer::Stats stats;
};

// Draws the triangles with the depth test on, handing `partCount` parts over before the rest.
Drawn draw(const char* threads, std::size_t partCount) {
    setenv("MYGL_THREADS", threads, 1);
    PipelineFixture f(32, 32);
    unsetenv("MYGL_THREADS");
    f.state.depthTest = true;
    f.pipeline.clear(true, 0, true, glrenderer::kDepthMax24);
    const std::vector<Vertex> vertices = randomTriangles(f, glrenderer::Pipeline::kPartVertices + 100);
    const std::span<const Vertex> all(vertices);
    const std::size_t partSize = glrenderer::Pipeline::kPartVertices;
    for (std::size_t i = 0; i < partCount; ++i)
        f.pipeline.submitPart(f.state, PrimitiveMode::Triangles, all.subspan(i * partSize, partSize));
    f.pipeline.submit(f.state, PrimitiveMode::Triangles, all.subspan(partCount * partSize));
    f.pipeline.finish();
    return {{f.framebuffer.color().begin(), f.framebuffer.color().end()},
            {f.framebuffer.depth().begin(), f.framebuffer.depth().end()},
            f.pipeline.stats()};
}

void expectSame(const Drawn& a, const Drawn& b) {
    EXPECT_EQ(a.color, b.color);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.stats.vertices, b.stats.vertices);
    EXPECT_EQ(a.stats.primitivesByMode, b.stats.primitivesByMode);
    EXPECT_EQ(a.stats.triangles, b.stats.triangles);
    EXPECT_EQ(a.stats.rasterized, b.stats.rasterized);
    EXPECT_EQ(a.stats.fragments, b.stats.fragments);
    EXPECT_EQ(a.stats.fragmentsPassed, b.stats.fragmentsPassed);
}

}  // namespace

TEST(Batches, ThreadedEqualsSingleThreaded) {
    const Drawn single = draw("1", 0);
    const Drawn threaded = draw("2", 0);
    EXPECT_GT(single.stats.fragmentsPassed, 0u);
    expectSame(single, threaded);
}

TEST(Batches, PrimitiveInPartsEqualsWholeAndCountsOnce) {
    const Drawn whole = draw("2", 0);
    const Drawn inParts = draw("2", 3);
    expectSame(whole, inParts);
    EXPECT_EQ(inParts.stats.primitivesByMode[static_cast<std::size_t>(PrimitiveMode::Triangles)], 1u);
    EXPECT_EQ(inParts.stats.vertices, 3 * glrenderer::Pipeline::kPartVertices + 300);
}
