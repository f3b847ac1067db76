// Facing, culling, decomposition orders and clipping of the exact pipeline.
#include <gtest/gtest.h>

#include "clip.h"
#include "decompose.h"
#include "pipeline_fixture.h"

using glrenderer::Face;
using glrenderer::PrimitiveMode;
using testing_support::PipelineFixture;

namespace {

// A counter-clockwise triangle in GL window coordinates (y up).
void drawCounterClockwise(PipelineFixture& f) {
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(14, 2), f.windowVertex(2, 14)});
}

}  // namespace

TEST(Culling, CounterClockwiseIsFrontByDefault) {
    PipelineFixture f(16, 16);
    f.state.cullEnabled = true;
    f.state.cullFace = Face::Back;
    drawCounterClockwise(f);
    EXPECT_EQ(f.pipeline.stats().rasterized, 1u);
    f.state.cullFace = Face::Front;
    drawCounterClockwise(f);
    EXPECT_EQ(f.pipeline.stats().culledFront, 1u);
}

TEST(Culling, FrontFaceClockwiseSwapsFacing) {
    PipelineFixture f(16, 16);
    f.state.cullEnabled = true;
    f.state.frontFaceCCW = false;
    drawCounterClockwise(f);
    EXPECT_EQ(f.pipeline.stats().culledBack, 1u);
    EXPECT_EQ(f.coveredPixels(), 0);
}

TEST(Culling, FrontAndBackCullsEveryTriangleButCountsItsFacing) {
    PipelineFixture f(16, 16);
    f.state.cullEnabled = true;
    f.state.cullFace = Face::FrontAndBack;
    drawCounterClockwise(f);
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(2, 14), f.windowVertex(14, 2)});
    EXPECT_EQ(f.pipeline.stats().culledFront, 1u);
    EXPECT_EQ(f.pipeline.stats().culledBack, 1u);
    EXPECT_EQ(f.pipeline.stats().rasterized, 0u);
}

TEST(Culling, TriangleThatSnapsToALineIsZeroArea) {
    PipelineFixture f(16, 16);
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(14, 2.001f), f.windowVertex(8, 2.0005f)});
    EXPECT_EQ(f.pipeline.stats().culledZeroArea, 1u);
}

TEST(Decomposition, FanAndPolygonOrders) {
    std::vector<std::array<std::uint32_t, 3>> fan, polygon;
    glrenderer::decomposeTriangles(PrimitiveMode::TriangleFan, 5, glrenderer::DecompositionPath::Direct, false,
                                   [&](const glrenderer::TriangleIndices& t) {
                                       fan.push_back({t.v[0], t.v[1], t.v[2]});
                                   });
    glrenderer::decomposeTriangles(PrimitiveMode::Polygon, 5, glrenderer::DecompositionPath::Direct, false,
                                   [&](const glrenderer::TriangleIndices& t) {
                                       polygon.push_back({t.v[0], t.v[1], t.v[2]});
                                   });
    using T = std::vector<std::array<std::uint32_t, 3>>;
    EXPECT_EQ(fan, (T{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
    EXPECT_EQ(polygon, (T{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}}));
}

TEST(Decomposition, QuadDiagonalDependsOnPathAndShading) {
    auto split = [](glrenderer::DecompositionPath path, bool v1v3Quads) {
        std::vector<std::array<std::uint32_t, 3>> out;
        glrenderer::decomposeTriangles(PrimitiveMode::Quads, 4, path, v1v3Quads,
                                       [&](const glrenderer::TriangleIndices& t) {
                                           out.push_back({t.v[0], t.v[1], t.v[2]});
                                       });
        return out;
    };
    using T = std::vector<std::array<std::uint32_t, 3>>;
    using glrenderer::DecompositionPath;
    EXPECT_EQ(split(DecompositionPath::Direct, false), (T{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(split(DecompositionPath::Direct, true), (T{{0, 1, 3}, {1, 2, 3}}));
    EXPECT_EQ(split(DecompositionPath::DrawModule, false), (T{{0, 1, 3}, {1, 2, 3}}));
}

TEST(Clipping, TriangleThroughTheNearPlaneBecomesAQuadrilateral) {
    const glrenderer::ClipVertex a{{0, 0, -2, 1}, {1, 0, 0, 1}};  // in front of the near plane
    const glrenderer::ClipVertex b{{0.5f, 0, 0, 1}, {0, 1, 0, 1}};
    const glrenderer::ClipVertex c{{0, 0.5f, 0, 1}, {0, 0, 1, 1}};
    const glrenderer::Outcode codes =
        glrenderer::clipOutcode(a.position) | glrenderer::clipOutcode(b.position) | glrenderer::clipOutcode(c.position);
    EXPECT_EQ(codes, 1u << 4);  // the near plane
    const auto polygon = glrenderer::clipTriangle(a, b, c, codes, {});
    ASSERT_EQ(polygon.count, 4);
    // Walking from v0 (outside): the cut on a-b, then b, c, and the cut on c-a.
    EXPECT_FLOAT_EQ(polygon.vertices[0].position.z, -polygon.vertices[0].position.w);
    EXPECT_EQ(polygon.vertices[1].position, b.position);
    EXPECT_EQ(polygon.vertices[2].position, c.position);
    EXPECT_FLOAT_EQ(polygon.vertices[3].position.z, -polygon.vertices[3].position.w);
    // b and c are the input vertices 1 and 2 (they keep their vertex-stage window positions).
    const std::array<int, 4> sources{glrenderer::kNewVertex, 1, 2, glrenderer::kNewVertex};
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(polygon.source[static_cast<std::size_t>(i)], sources[static_cast<std::size_t>(i)]);
    for (int i = 0; i < polygon.count; ++i) {
        const glm::vec4& p = polygon.vertices[static_cast<std::size_t>(i)].position;
        EXPECT_GE(p.z, -p.w - 1e-6f);
    }
}

TEST(Clipping, NonFiniteVerticesDrawNothingAndDoNotCrash) {
    PipelineFixture f(16, 16);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    f.draw(PrimitiveMode::Triangles, {{{nan, 0, 0, 1}, {1, 1, 1, 1}}, f.windowVertex(14, 2), f.windowVertex(2, 14)});
    f.draw(PrimitiveMode::Triangles, {{{inf, 0, 0, 1}, {1, 1, 1, 1}}, f.windowVertex(14, 2), f.windowVertex(2, 14)});
    f.draw(PrimitiveMode::Triangles, {{{0, 0, 0, 0}, {1, 1, 1, 1}}, f.windowVertex(14, 2), f.windowVertex(2, 14)});
    f.draw(PrimitiveMode::Triangles,
           {{{1e30f, -1e30f, 0, 1e-30f}, {1, 1, 1, 1}}, f.windowVertex(14, 2), f.windowVertex(2, 14)});
    EXPECT_EQ(f.pipeline.stats().triangles, 4u);
    const auto& s = f.pipeline.stats();
    EXPECT_EQ(s.triangles,
              s.clippedAway + s.culledBack + s.culledFront + s.culledZeroArea + s.rasterized - s.clipCreated);
}

TEST(Stats, CountsAddUpForAClippedMesh) {
    PipelineFixture f(32, 32);
    f.state.cullEnabled = true;
    std::vector<glrenderer::Vertex> strip;
    for (int i = 0; i < 12; ++i)
        strip.push_back(f.windowVertex(-20.0f + 7.0f * static_cast<float>(i), i % 2 ? 40.0f : -5.0f));
    f.draw(PrimitiveMode::TriangleStrip, strip);
    const auto& s = f.pipeline.stats();
    EXPECT_EQ(s.triangles, 10u);
    EXPECT_GT(s.clipCreated, 0u);
    EXPECT_EQ(s.triangles,
              s.clippedAway + s.culledBack + s.culledFront + s.culledZeroArea + s.rasterized - s.clipCreated);
}
