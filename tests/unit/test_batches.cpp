// Batches drawn on the pipeline's own thread, and long primitives handed over in parts, give
// the same pixels, depths and counts as drawing on the caller's thread and as merged blocks.
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

// Draws the triangles with the depth test on, as one primitive (handed over in parts when long)
// or as one glBegin/glEnd block per triangle (merged into batches).
Drawn draw(const char* threads, bool onePrimitive) {
    setenv("MYGL_THREADS", threads, 1);
    PipelineFixture f(32, 32);
    unsetenv("MYGL_THREADS");
    f.state.depthTest = true;
    f.pipeline.clear(true, 0, true, glrenderer::kDepthMax24);
    const std::vector<Vertex> vertices = randomTriangles(f, glrenderer::Pipeline::kPartVertices + 100);
    const std::span<const Vertex> all(vertices);
    if (onePrimitive) {
        f.pipeline.submit(f.state, PrimitiveMode::Triangles, all);
    } else {
        for (std::size_t i = 0; i < all.size(); i += 3)
            f.pipeline.submit(f.state, PrimitiveMode::Triangles, all.subspan(i, 3));
    }
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
    const Drawn single = draw("1", true);
    const Drawn threaded = draw("2", true);
    EXPECT_GT(single.stats.fragmentsPassed, 0u);
    expectSame(single, threaded);
}

TEST(Batches, LongPrimitiveEqualsMergedBlocksAndCountsOnce) {
    const Drawn merged = draw("2", false);
    const Drawn onePrimitive = draw("2", true);
    EXPECT_EQ(onePrimitive.color, merged.color);
    EXPECT_EQ(onePrimitive.depth, merged.depth);
    EXPECT_EQ(onePrimitive.stats.fragmentsPassed, merged.stats.fragmentsPassed);
    EXPECT_EQ(onePrimitive.stats.primitivesByMode[static_cast<std::size_t>(PrimitiveMode::Triangles)], 1u);
    EXPECT_EQ(onePrimitive.stats.vertices, 3 * (glrenderer::Pipeline::kPartVertices + 100));
}
