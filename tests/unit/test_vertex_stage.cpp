// The vertex stage's FMA version against the scalar operations it reproduces (ColumnTransform,
// clipOutcode and ViewportTransform::apply): the same clip positions, outcodes and window
// vertices bit for bit, on ordinary
// vertices and on the ones that break things (w = 0, negative w, NaN, infinities, huge values).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "clip.h"
#include "column_transform.h"
#include "cpu_features.h"
#include "vertex_stage.h"

using namespace glrenderer;

namespace {

// Equal bits, or both NaN (a NaN's payload is not part of the contract).
bool sameFloat(float a, float b) {
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b) || (std::isnan(a) && std::isnan(b));
}

std::vector<Vertex> testVertices() {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float special[] = {0.0f, -0.0f, 1.0f, -1.0f, 1e-30f, -1e-30f, 1e30f, -1e30f, inf, -inf, nan, 0.5f, 3.0f};
    std::vector<Vertex> vertices;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f), w(-1.0f, 4.0f);
    std::uniform_int_distribution<std::size_t> pick(0, std::size(special) - 1);
    for (int i = 0; i < 4001; ++i) {  // odd: the FMA version stages the last one alone
        Vertex v;
        v.position = {coordinate(random), coordinate(random), coordinate(random), w(random)};
        if (i % 4 == 0) v.position[i / 4 % 4] = special[pick(random)];  // one special coordinate
        if (i % 16 == 1)
            v.position = {special[pick(random)], special[pick(random)], special[pick(random)], special[pick(random)]};
        v.color = {coordinate(random), 0.25f, i % 7 == 0 ? nan : 0.5f, 1.0f};
        vertices.push_back(v);
    }
    return vertices;
}

}  // namespace

TEST(VertexStage, FmaVersionMatchesTheScalarOperationsBitForBit) {
    if (!cpuHasFma()) GTEST_SKIP() << "this CPU has no FMA";
    const std::vector<Vertex> vertices = testVertices();
    DrawState state;
    state.viewport = {13, -7, 641, 479};
    state.depthNear = 0.25f;
    state.depthFar = 0.75f;
    const ViewportTransform viewport(state, 500);
    // A projection with a non-trivial w row, times a rotation and a translation.
    const Matrix mvp = {0.8f, 0.1f,  -0.3f, -0.3f, -0.2f, 1.3f,  0.05f, 0.05f,
                        0.4f, -0.1f, -1.0f, -1.0f, 0.25f, -0.5f, 2.0f,  3.0f};
    const ColumnTransform toClip(mvp);
    std::vector<glm::vec4> clip(vertices.size());
    std::vector<Outcode> outcodes(vertices.size());
    std::vector<WindowVertex> window(vertices.size());
    const StagedSummary staged =
        stageVerticesFma(vertices, mvp, viewport, {clip.data(), outcodes.data(), window.data()});
    Outcode expectedAnyOutside = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        glm::vec4 expectedClip;
        _mm_storeu_ps(&expectedClip.x, toClip.apply(vertices[i].position));
        const Outcode outcode = clipOutcode(expectedClip);
        const WindowVertex expected = viewport.apply(expectedClip, vertices[i].color);
        expectedAnyOutside |= outcode;
        ASSERT_EQ(outcodes[i], outcode) << "vertex " << i;
        const float got[] = {clip[i].x,   clip[i].y,   clip[i].z,      clip[i].w,         window[i].x,
                             window[i].y, window[i].z, window[i].invW, window[i].color.r, window[i].color.b};
        const float want[] = {expectedClip.x, expectedClip.y, expectedClip.z, expectedClip.w,   expected.x,
                              expected.y,     expected.z,     expected.invW,  expected.color.r, expected.color.b};
        for (std::size_t k = 0; k < std::size(got); ++k) {
            ASSERT_TRUE(sameFloat(got[k], want[k]))
                << "vertex " << i << " component " << k << ": " << got[k] << " vs " << want[k];
        }
    }
    EXPECT_EQ(staged.anyOutside, expectedAnyOutside);
    EXPECT_TRUE(staged.alphaOne);  // every test vertex's alpha is 1
}

// Whether every colour of a batch has alpha 1 (what lets its triangles store alpha 255 without
// interpolating it, FragmentKey::alphaOne): one vertex a hair below, or NaN, makes it false.
TEST(VertexStage, FindsWhetherEveryColourHasAlphaOne) {
    Framebuffer framebuffer(8, 8);
    Pipeline pipeline(framebuffer);
    DrawState state;
    state.viewport = {0, 0, 8, 8};
    std::vector<Vertex> vertices(9, Vertex{{0.5f, -0.25f, 0.0f, 1.0f}, {0.2f, 0.4f, 0.6f, 1.0f}});
    SubmittedBatch batch;
    batch.state = pipeline.intern(state);
    batch.mode = PrimitiveMode::Triangles;
    batch.vertices = vertices;
    VertexStage stage(vertices.size());
    const ViewportTransform viewport(state, framebuffer.height());
    std::vector<glm::vec4> clip(vertices.size());
    std::vector<Outcode> outcodes(vertices.size());
    std::vector<WindowVertex> window(vertices.size());
    // The stage's answer, which each version of the pass gives too.
    const auto alphaOne = [&] {
        const StagedVertices out{clip.data(), outcodes.data(), window.data()};
        const bool scalar = stageVertices(vertices, kIdentity, viewport, out).alphaOne;
        if (cpuHasFma()) {
            EXPECT_EQ(stageVerticesFma(vertices, kIdentity, viewport, out).alphaOne, scalar);
        }
        stage.run(batch, viewport);
        EXPECT_EQ(stage.alphaOne(), scalar);
        return scalar;
    };
    EXPECT_TRUE(alphaOne());
    // Each place (the FMA version's two halves, and the odd count's last vertex, staged in both).
    for (Vertex& v : vertices) {
        for (const float alpha : {std::nextafter(1.0f, 0.0f), std::numeric_limits<float>::quiet_NaN(), 0.0f}) {
            v.color.a = alpha;
            EXPECT_FALSE(alphaOne()) << alpha << " at vertex " << &v - vertices.data();
        }
        v.color.a = 1.0f;
    }
    EXPECT_TRUE(alphaOne());
    vertices[4].color = {1.0f, 1.0f, 1.0f, 0.5f};  // ones, but not in alpha
    EXPECT_FALSE(alphaOne());
}
