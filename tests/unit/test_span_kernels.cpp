// The fast kernels (exact spans, scalar, AVX2 or AVX-512 shading, AVX-512 blocks for narrow
// triangles) against the per-pixel reference kernel: same colors, depths and counts, bit for
// bit, on random triangles in every fragment state (perspective or not), whole or cut to a
// rectangle as tiles are.
#include <gtest/gtest.h>

#include <random>

#include "glrenderer/color_convert.h"
#include "cpu_features.h"
#include "raster_span.h"
#include "window_vertex.h"

using namespace glrenderer;

namespace {

constexpr int kWidth = 97, kHeight = 61;  // odd sizes exercise the 8-pixel tails

struct Target {
    Framebuffer framebuffer{kWidth, kHeight};
    FragmentCounts counts;
};

WindowVertex randomVertex(std::mt19937& random, float spread) {
    std::uniform_real_distribution<float> position(-spread, spread), unit(0.0f, 1.0f), w(0.2f, 4.0f);
    WindowVertex v;
    v.x = kWidth / 2.0f + position(random);
    v.y = kHeight / 2.0f + position(random);
    v.z = unit(random) * 1.2f - 0.1f;  // slightly outside [0, 1] to exercise the clamp
    v.invW = 1.0f / w(random);
    v.color = {unit(random) * 1.2f - 0.1f, unit(random), unit(random), unit(random)};
    return v;
}

}  // namespace

TEST(SpanKernels, MatchThePerPixelKernelBitForBit) {
    std::mt19937 random(5);
    std::uniform_int_distribution<int> depthFunc(0, 7), coin(0, 1);
    std::uniform_int_distribution<std::uint32_t> depth(0, kDepthMax24);
    std::uniform_int_distribution<int> column(0, kWidth - 1), row(0, kHeight - 1);
    std::vector<std::pair<const char*, ExactKernels>> kernels{{"scalar", {shadeSpanScalar, nullptr}}};
    if (cpuHasAvx2Fma()) kernels.push_back({"avx2", {shadeSpanAvx2, nullptr}});
    if (cpuHasAvx512()) {
        kernels.push_back({"avx512", {shadeSpanAvx512, nullptr}});
        kernels.push_back({"avx512 narrow blocks", {shadeSpanAvx512, shadeNarrowTriangleAvx512}});
    }
    int drawn = 0;
    for (int i = 0; i < 3000; ++i) {
        const float spread = i % 3 == 0 ? 3.0f : (i % 3 == 1 ? 30.0f : 400.0f);
        SetupTriangle setup{{randomVertex(random, spread), randomVertex(random, spread), randomVertex(random, spread)},
                            {}, 0, {0.3f, 0.6f, 0.9f, 1.0f}};
        // Every fourth triangle has w = 1 at every vertex, as orthographic scenes do: the fast
        // kernels then skip the division by 1 / w.
        if (i % 4 == 3) {
            for (WindowVertex& v : setup.v) v.invW = 1.0f;
        }
        for (int k = 0; k < 3; ++k) setup.fixed[k] = snap(setup.v[k]);
        setup.area = fixedArea(setup.fixed[0], setup.fixed[1], setup.fixed[2]);
        if (setup.area == 0) continue;
        DrawState state;
        state.depthTest = coin(random);
        state.depthFunc = static_cast<CompareFunc>(depthFunc(random));
        state.depthWrite = coin(random);
        state.shadeModel = coin(random) ? ShadeModel::Smooth : ShadeModel::Flat;
        RasterTriangle triangle;
        if (!prepareTriangle(setup, state, Methods{}, kWidth, kHeight, triangle)) continue;
        ++drawn;

        std::vector<std::uint32_t> initialDepth(kWidth * kHeight);
        for (auto& d : initialDepth) d = depth(random);
        // Every other triangle is drawn within a random rectangle, as a tile draws its part.
        PixelRect rect{0, kWidth - 1, 0, kHeight - 1};
        if (i % 2) {
            const int x0 = column(random), x1 = column(random), y0 = row(random), y1 = row(random);
            rect = {std::min(x0, x1), std::max(x0, x1), std::min(y0, y1), std::max(y0, y1)};
        }
        Target expected;
        std::copy(initialDepth.begin(), initialDepth.end(), expected.framebuffer.depth().begin());
        rasterizeTriangleExact(triangle, rect, expected.framebuffer, expected.counts);
        for (const auto& [name, kernel] : kernels) {
            Target actual;
            std::copy(initialDepth.begin(), initialDepth.end(), actual.framebuffer.depth().begin());
            rasterizeTriangleSpans(triangle, rect, actual.framebuffer, actual.counts, kernel);
            ASSERT_TRUE(std::equal(expected.framebuffer.color().begin(), expected.framebuffer.color().end(),
                                   actual.framebuffer.color().begin())) << name << " triangle " << i;
            ASSERT_TRUE(std::equal(expected.framebuffer.depth().begin(), expected.framebuffer.depth().end(),
                                   actual.framebuffer.depth().begin())) << name << " triangle " << i;
            ASSERT_EQ(expected.counts.fragments, actual.counts.fragments) << name;
            ASSERT_EQ(expected.counts.passed, actual.counts.passed) << name;
        }
    }
    EXPECT_GT(drawn, 2000);
}
