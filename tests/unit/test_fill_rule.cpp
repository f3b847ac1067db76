// The fill rule and snapping of the exact method, pinned on hand-checked cases from the
// reference's rules (../shared/reference-rules.md).
#include <gtest/gtest.h>

#include <random>

#include "pipeline_fixture.h"

using glrenderer::PrimitiveMode;
using testing_support::PipelineFixture;

TEST(FillRule, RightTriangleCovers378Pixels) {
    PipelineFixture f(32, 32);
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(30, 2), f.windowVertex(2, 30)});
    EXPECT_EQ(f.coveredPixels(), 378);
    EXPECT_EQ(f.pipeline.stats().rasterized, 1u);
    EXPECT_EQ(f.pipeline.stats().fragments, 378u);
}

TEST(FillRule, WindingDoesNotChangeCoverage) {
    PipelineFixture f(32, 32);
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(2, 30), f.windowVertex(30, 2)});
    EXPECT_EQ(f.coveredPixels(), 378);
}

// A square of pixel-center-aligned edges: left and bottom edges own their centers, right and
// top edges do not, so a square from center 2.5 to center 6.5 covers columns and rows 2..5.
TEST(FillRule, LeftAndBottomEdgesOwnCentersRightAndTopDoNot) {
    PipelineFixture f(10, 10);
    f.draw(PrimitiveMode::Quads, {f.windowVertex(2.5f, 2.5f), f.windowVertex(6.5f, 2.5f), f.windowVertex(6.5f, 6.5f),
                                  f.windowVertex(2.5f, 6.5f)});
    EXPECT_EQ(f.coveredPixels(), 16);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x)
            EXPECT_EQ(f.pixel(x, y) != 0, x >= 2 && x <= 5 && y >= 2 && y <= 5) << x << "," << y;
}

// Snapping ties round to even: 4.5 + 1/512 snaps onto the center of pixel 4 (a left edge owns
// it), 4.5 + 1.5/512 snaps past it.
TEST(FillRule, SnappingRoundsTiesToEven) {
    for (const auto& [offset, covers] : {std::pair{1.0f / 512, true}, std::pair{1.5f / 512, false}}) {
        PipelineFixture f(10, 10);
        const float left = 4.5f + offset;
        f.draw(PrimitiveMode::Quads,
               {f.windowVertex(left, 1), f.windowVertex(8, 1), f.windowVertex(8, 9), f.windowVertex(left, 9)});
        EXPECT_EQ(f.pixel(4, 5) != 0, covers) << "offset " << offset;
    }
}

// Watertightness: a mesh of jittered vertices drawn with every triangle counted per pixel.
TEST(FillRule, SharedEdgesAreCoveredExactlyOnce) {
    constexpr int kSize = 64, kGrid = 8;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> jitter(-2.5f, 2.5f);
    std::vector<std::vector<std::pair<float, float>>> points(kGrid + 1);
    for (int j = 0; j <= kGrid; ++j)
        for (int i = 0; i <= kGrid; ++i) {
            const bool border = i == 0 || j == 0 || i == kGrid || j == kGrid;
            const float x = static_cast<float>(i * kSize / kGrid) + (border ? 0 : jitter(random));
            const float y = static_cast<float>(j * kSize / kGrid) + (border ? 0 : jitter(random));
            points[static_cast<std::size_t>(j)].push_back({x, y});
        }
    std::vector<int> hits(kSize * kSize, 0);
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i)
            for (int half = 0; half < 2; ++half) {
                PipelineFixture f(kSize, kSize);
                auto p = [&](int di, int dj) {
                    const auto& [x, y] = points[static_cast<std::size_t>(j + dj)][static_cast<std::size_t>(i + di)];
                    return f.windowVertex(x, y);
                };
                if (half == 0)
                    f.draw(PrimitiveMode::Triangles, {p(0, 0), p(1, 0), p(1, 1)});
                else
                    f.draw(PrimitiveMode::Triangles, {p(0, 0), p(1, 1), p(0, 1)});
                for (int k = 0; k < kSize * kSize; ++k)
                    hits[static_cast<std::size_t>(k)] += f.framebuffer.color()[static_cast<std::size_t>(k)] != 0;
            }
    for (int k = 0; k < kSize * kSize; ++k)
        ASSERT_EQ(hits[static_cast<std::size_t>(k)], 1) << "pixel " << k % kSize << "," << k / kSize;
}
