// Batches drawn on the pipeline's own thread, long primitives handed over in parts, and chunks
// set up ahead by the program's thread give the same pixels, depths and counts as drawing on
// the caller's thread, as merged blocks, and as the batch thread drawing the chunk itself.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <random>
#include <vector>

#include "batch_drawer.h"
#include "batch_setup.h"
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
        f.pipeline.submit(f.pipeline.intern(f.state), PrimitiveMode::Triangles, all);
    } else {
        for (std::size_t i = 0; i < all.size(); i += 3)
            f.pipeline.submit(f.pipeline.intern(f.state), PrimitiveMode::Triangles, all.subspan(i, 3));
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

namespace {

constexpr int kMixedBatches = 24;

// A chunk of triangle batches in every filled mode: perspective, clipped at every plane, culled
// or not, flat or smooth, colors per vertex or not; all of them, or only batch `only`.
glrenderer::BatchChunk mixedTriangleChunk(int only = -1) {
    using glrenderer::BatchEntry;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> position(-1.6f, 1.6f), w(0.5f, 2.0f), unit(0.0f, 1.0f);
    glrenderer::BatchChunk chunk(0, 0);
    const PrimitiveMode modes[] = {PrimitiveMode::Triangles, PrimitiveMode::TriangleStrip, PrimitiveMode::TriangleFan,
                                   PrimitiveMode::Quads,     PrimitiveMode::QuadStrip,     PrimitiveMode::Polygon};
    for (int i = 0; i < kMixedBatches; ++i) {
        BatchEntry entry;
        entry.mode = modes[i % 6];
        glrenderer::DrawState state;
        state.viewport = {0, 0, 40, 30};
        state.depthTest = i % 3 != 0;
        state.cullEnabled = i % 4 == 1;
        state.shadeModel = i % 5 == 2 ? glrenderer::ShadeModel::Flat : glrenderer::ShadeModel::Smooth;
        entry.state = std::make_shared<const glrenderer::DrawState>(state);
        entry.colorsPerVertex = i % 7 != 3;
        entry.first = chunk.vertices.size();
        entry.count = 12;
        for (std::size_t k = 0; k < entry.count; ++k) {
            const float cw = w(random);
            chunk.vertices.push_back({{position(random) * cw, position(random) * cw, position(random) * cw, cw},
                                      {unit(random), unit(random), unit(random), 1.0f}});
        }
        if (only < 0 || only == i) chunk.batches.push_back(entry);
    }
    return chunk;
}

Drawn drawChunk(glrenderer::BatchChunk chunk, bool setUpFirst) {
    glrenderer::Framebuffer framebuffer(40, 30);
    glrenderer::BatchDrawer drawer(framebuffer);
    drawer.clearAtFlush(true, 0, true, glrenderer::kDepthMax24);
    glrenderer::ArenaWriter writer(drawer.triangleArena());
    if (setUpFirst) {
        glrenderer::BatchSetup setup(framebuffer, 0);
        EXPECT_TRUE(setup.setUp(chunk, writer));
        EXPECT_TRUE(chunk.setUp);
    }
    drawer.draw(chunk);
    drawer.flush();
    return {{framebuffer.color().begin(), framebuffer.color().end()},
            {framebuffer.depth().begin(), framebuffer.depth().end()},
            drawer.stats()};
}

}  // namespace

// The poster's thread may set a chunk's triangles up before the batch thread gets to it: the
// whole chunk (order across batches) and each batch alone (each batch's state) draw the same.
TEST(Batches, ChunkSetUpAheadDrawsAsTheBatchThreadWould) {
    for (int only = -1; only < kMixedBatches; ++only) {
        SCOPED_TRACE(only);
        const Drawn drawn = drawChunk(mixedTriangleChunk(only), false);
        const Drawn setUpAhead = drawChunk(mixedTriangleChunk(only), true);
        if (only < 0) {
            EXPECT_GT(drawn.stats.fragmentsPassed, 0u);
            EXPECT_GT(drawn.stats.clipCreated, 0u);
            EXPECT_GT(drawn.stats.culledBack + drawn.stats.culledFront, 0u);
        }
        expectSame(drawn, setUpAhead);
        EXPECT_EQ(drawn.stats.clippedAway, setUpAhead.stats.clippedAway);
        EXPECT_EQ(drawn.stats.clipCreated, setUpAhead.stats.clipCreated);
        EXPECT_EQ(drawn.stats.culledBack, setUpAhead.stats.culledBack);
        EXPECT_EQ(drawn.stats.culledFront, setUpAhead.stats.culledFront);
        EXPECT_EQ(drawn.stats.culledZeroArea, setUpAhead.stats.culledZeroArea);
    }
}

// Lines and unfilled polygons are drawn at once, in order with the tiles: not set up ahead.
TEST(Batches, ChunkWithLinesIsNotSetUpAhead) {
    glrenderer::BatchChunk chunk = mixedTriangleChunk();
    chunk.batches[5].mode = PrimitiveMode::Lines;
    glrenderer::Framebuffer framebuffer(40, 30);
    glrenderer::TriangleArena arena;
    glrenderer::ArenaWriter writer(arena);
    glrenderer::BatchSetup setup(framebuffer, 0);
    EXPECT_FALSE(setup.setUp(chunk, writer));
    EXPECT_FALSE(chunk.setUp);
    EXPECT_TRUE(chunk.setUpTriangles.empty());
    chunk = mixedTriangleChunk();
    glrenderer::DrawState lines = *chunk.batches[2].state;
    lines.polygonBack = glrenderer::PolygonMode::Line;
    chunk.batches[2].state = std::make_shared<const glrenderer::DrawState>(lines);
    EXPECT_FALSE(setup.setUp(chunk, writer));
}
