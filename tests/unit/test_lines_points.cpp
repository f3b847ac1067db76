// Lines, points and polygon mode LINE/POINT: the reference's rules, each measured with OSMesa
// (Mesa 22.3.6 llvmpipe) on Debian 12. Framebuffers are 32x32 so that window positions given in
// pixels map to clip coordinates and back without rounding.
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "glrenderer/color_convert.h"
#include "pipeline_fixture.h"

using glrenderer::Face;
using glrenderer::PolygonMode;
using glrenderer::PrimitiveMode;
using glrenderer::ShadeModel;
using testing_support::PipelineFixture;

namespace {

using PixelSet = std::set<std::pair<int, int>>;

PixelSet covered(const PipelineFixture& f) {
    PixelSet pixels;
    for (int y = 0; y < f.framebuffer.height(); ++y) {
        for (int x = 0; x < f.framebuffer.width(); ++x) {
            if (f.pixel(x, y) != 0) pixels.insert({x, y});
        }
    }
    return pixels;
}

PixelSet row(int y, int x0, int x1) {
    PixelSet pixels;
    for (int x = x0; x <= x1; ++x) pixels.insert({x, y});
    return pixels;
}

PixelSet square(int x0, int y0, int size) {
    PixelSet pixels;
    for (int y = y0; y < y0 + size; ++y) {
        for (int x = x0; x < x0 + size; ++x) pixels.insert({x, y});
    }
    return pixels;
}

PixelSet drawLine(float x0, float y0, float x1, float y1, float width = 1.0f) {
    PipelineFixture f(32, 32);
    f.state.lineWidth = width;
    f.draw(PrimitiveMode::Lines, {f.windowVertex(x0, y0), f.windowVertex(x1, y1)});
    return covered(f);
}

PixelSet drawPoint(float x, float y, float size) {
    PipelineFixture f(32, 32);
    f.state.pointSize = size;
    f.draw(PrimitiveMode::Points, {f.windowVertex(x, y)});
    return covered(f);
}

}  // namespace

TEST(LineRule, HorizontalLineLightsStartPixelButNotEndPixel) {
    EXPECT_EQ(drawLine(2.5f, 2.5f, 8.5f, 2.5f), row(2, 2, 7));
}

TEST(LineRule, DirectionMatters) { EXPECT_EQ(drawLine(8.5f, 2.5f, 2.5f, 2.5f), row(2, 3, 8)); }

TEST(LineRule, LineOnIntegerYLightsTheRowBelow) { EXPECT_EQ(drawLine(2.5f, 2.0f, 8.5f, 2.0f), row(1, 2, 7)); }

TEST(LineRule, LineOnIntegerXLightsTheColumnLeft) {
    PixelSet column;
    for (int y = 2; y <= 7; ++y) column.insert({1, y});
    EXPECT_EQ(drawLine(2.0f, 2.5f, 2.0f, 8.5f), column);
    PixelSet down;  // downwards the end pixel is left out, the start pixel lit: y = 3..8
    for (int y = 3; y <= 8; ++y) down.insert({1, y});
    EXPECT_EQ(drawLine(2.0f, 8.5f, 2.0f, 2.5f), down);
}

TEST(LineRule, ZeroLengthAndLinesThatStayInsideOnePixelDrawNothing) {
    EXPECT_TRUE(drawLine(3.3f, 3.3f, 3.3f, 3.3f).empty());
    EXPECT_TRUE(drawLine(3.2f, 3.2f, 3.7f, 3.4f).empty());
}

TEST(LineRule, WidthIsRoundedToAnIntegerWithHalvesUp) {
    PixelSet two = row(4, 2, 7);
    two.merge(row(5, 2, 7));
    EXPECT_EQ(drawLine(2.5f, 5.5f, 8.5f, 5.5f, 2.0f), two);
    EXPECT_EQ(drawLine(2.5f, 5.0f, 8.5f, 5.0f, 2.0f), two);
    PixelSet three = two;
    three.merge(row(6, 2, 7));
    EXPECT_EQ(drawLine(2.5f, 5.5f, 8.5f, 5.5f, 3.0f), three);
    EXPECT_EQ(drawLine(2.5f, 5.5f, 8.5f, 5.5f, 2.5f), three);
    EXPECT_EQ(drawLine(2.5f, 5.5f, 8.5f, 5.5f, 0.25f), row(5, 2, 7));  // at least one pixel
}

TEST(LineRule, EndOnAPixelCenterOfALeftwardLine) {
    // Leftward x-major line ending on a pixel center: measured as the reference draws it (its
    // "already drawing the end" test counts an end on the center as drawn).
    // The middle pixel center (10.5, 14.5) lies exactly on the quad's upper edge.
    PixelSet expected = {{4, 17},  {5, 17},  {6, 16},  {7, 15},  {8, 15},  {9, 14},  {10, 14},
                         {11, 13}, {12, 12}, {13, 12}, {14, 11}, {15, 10}, {16, 10}, {17, 9},
                         {18, 8},  {19, 8},  {20, 7},  {21, 6},  {22, 6}};
    EXPECT_EQ(drawLine(4.0f, 18.25f, 23.5f, 5.5f), expected);
}

TEST(LineRule, StripAndLoopShareEndsAndTheLoopClosesFromLastToFirst) {
    PipelineFixture strip(32, 32);
    strip.draw(PrimitiveMode::LineStrip,
               {strip.windowVertex(2.5f, 2.5f), strip.windowVertex(8.5f, 2.5f), strip.windowVertex(8.5f, 8.5f)});
    PipelineFixture loop(32, 32);
    loop.draw(PrimitiveMode::LineLoop,
              {loop.windowVertex(2.5f, 2.5f), loop.windowVertex(8.5f, 2.5f), loop.windowVertex(8.5f, 8.5f)});
    PixelSet closed = covered(strip);
    closed.merge(drawLine(8.5f, 8.5f, 2.5f, 2.5f));
    EXPECT_EQ(covered(loop), closed);
    EXPECT_NE(drawLine(8.5f, 8.5f, 2.5f, 2.5f), drawLine(2.5f, 2.5f, 8.5f, 8.5f));
}

TEST(LineColor, FlatLinesTakeTheSecondVertexColor) {
    PipelineFixture f(32, 32);
    f.state.shadeModel = ShadeModel::Flat;
    f.draw(PrimitiveMode::Lines,
           {f.windowVertex(2.5f, 2.5f, 0, {1, 0, 0, 1}), f.windowVertex(8.5f, 2.5f, 0, {0, 0, 1, 1})});
    for (int x = 2; x <= 7; ++x) EXPECT_EQ(f.pixel(x, 2), 0xFFFF0000u) << x;
}

TEST(LineColor, SmoothLinesInterpolateAlongTheMajorAxis) {
    PipelineFixture f(32, 32);
    f.draw(PrimitiveMode::Lines,
           {f.windowVertex(2.5f, 2.5f, 0, {0, 0, 0, 1}), f.windowVertex(10.5f, 4.5f, 0, {1, 1, 1, 1})});
    // At pixel x the value is (x - 2) / 8 along x whatever the row (values measured in OSMesa).
    EXPECT_EQ(f.pixel(2, 2) & 0xFF, 0u);
    EXPECT_EQ(f.pixel(6, 3) & 0xFF, 128u);
    EXPECT_EQ(f.pixel(9, 4) & 0xFF, 223u);
}

TEST(LineDepth, NearerLineWinsWhateverTheOrder) {
    for (bool nearFirst : {true, false}) {
        PipelineFixture f(32, 32);
        f.framebuffer.clearDepth(glrenderer::kDepthMax24);
        f.state.depthTest = true;
        const auto nearLine = [&] {
            f.draw(PrimitiveMode::Lines,
                   {f.windowVertex(2.5f, 5.5f, -0.5f, {1, 0, 0, 1}), f.windowVertex(12.5f, 5.5f, -0.5f, {1, 0, 0, 1})});
        };
        const auto farLine = [&] {
            f.draw(PrimitiveMode::Lines,
                   {f.windowVertex(7.5f, 0.5f, 0.5f, {0, 1, 0, 1}), f.windowVertex(7.5f, 10.5f, 0.5f, {0, 1, 0, 1})});
        };
        if (nearFirst) {
            nearLine();
            farLine();
        } else {
            farLine();
            nearLine();
        }
        EXPECT_EQ(f.pixel(7, 5), 0xFF0000FFu);
        EXPECT_EQ(f.pixel(7, 3), 0xFF00FF00u);
    }
}

TEST(LineClipping, LineLeavingTheViewportIsCutAtItsEdge) {
    PipelineFixture f(32, 32);
    f.state.viewport = {0, 0, 16, 32};  // the right half of the buffer is outside the viewport
    // y = 8 in window pixels: an integer row, so row 7 lights.
    f.draw(PrimitiveMode::Lines, {{{-0.5f, -0.5f, 0, 1}, {1, 1, 1, 1}}, {{3.0f, -0.5f, 0, 1}, {1, 1, 1, 1}}});
    EXPECT_EQ(covered(f), row(7, 4, 15));
}

TEST(PointRule, SizeOneLightsThePixelHoldingTheSnappedCenter) {
    EXPECT_EQ(drawPoint(3.0f, 3.0f, 1), PixelSet({{3, 3}}));
    EXPECT_EQ(drawPoint(5.99f, 5.5f, 1), PixelSet({{5, 5}}));
    EXPECT_EQ(drawPoint(4.999f, 4.999f, 1), PixelSet({{5, 5}}));  // snapped to 1/256 first
}

TEST(PointRule, OddSizesGrowAroundThePixelEvenSizesAroundTheNearestCorner) {
    EXPECT_EQ(drawPoint(3.0f, 3.0f, 2), square(2, 2, 2));
    EXPECT_EQ(drawPoint(6.5f, 7.5f, 2), square(6, 7, 2));
    EXPECT_EQ(drawPoint(3.0f, 3.0f, 3), square(2, 2, 3));
    EXPECT_EQ(drawPoint(6.5f, 7.5f, 3), square(5, 6, 3));
    EXPECT_EQ(drawPoint(6.5f, 7.5f, 2.5f), square(6, 7, 2));  // halves round down
}

TEST(PointRule, ClippedByTheCenter) {
    PipelineFixture f(32, 32);
    f.state.pointSize = 5;
    f.state.viewport = {0, 0, 16, 32};
    f.draw(PrimitiveMode::Points, {{{1.01f, 0.0f, 0, 1}, {1, 1, 1, 1}}});
    EXPECT_EQ(f.coveredPixels(), 0);
    f.draw(PrimitiveMode::Points, {{{0.99f, 0.0f, 0, 1}, {1, 1, 1, 1}}});
    EXPECT_EQ(f.coveredPixels(), 25);  // drawn whole, beyond the viewport's edge
}

TEST(PointRule, StatsCountFragments) {
    PipelineFixture f(32, 32);
    f.state.pointSize = 3;
    f.draw(PrimitiveMode::Points, {f.windowVertex(5, 5), f.windowVertex(0.2f, 0.2f)});
    EXPECT_EQ(f.pipeline.stats().fragments, 9u + 4u);  // the second is cut by the buffer
    EXPECT_EQ(f.pipeline.stats().pixelsWritten, 13u);
}

TEST(PolygonMode, QuadOutlineHidesTheDiagonal) {
    PipelineFixture f(32, 32);
    f.state.polygonFront = f.state.polygonBack = PolygonMode::Line;
    f.draw(PrimitiveMode::Quads, {f.windowVertex(2.5f, 2.5f), f.windowVertex(12.5f, 2.5f), f.windowVertex(12.5f, 12.5f),
                                  f.windowVertex(2.5f, 12.5f)});
    EXPECT_EQ(f.pixel(7, 7), 0u);
    EXPECT_EQ(f.coveredPixels(), 40);
    EXPECT_NE(f.pixel(2, 7), 0u);
    EXPECT_NE(f.pixel(12, 7), 0u);
}

TEST(PolygonMode, EdgeFlagHidesTheEdgeStartingAtTheVertex) {
    PipelineFixture f(32, 32);
    f.state.polygonFront = PolygonMode::Line;
    auto v0 = f.windowVertex(2.5f, 2.5f);
    v0.edgeFlag = false;  // hides v0 -> v1, the bottom edge
    f.draw(PrimitiveMode::Polygon,
           {v0, f.windowVertex(12.5f, 2.5f), f.windowVertex(12.5f, 12.5f), f.windowVertex(2.5f, 12.5f)});
    EXPECT_EQ(f.pixel(7, 2), 0u);
    EXPECT_NE(f.pixel(7, 12), 0u);
    EXPECT_EQ(f.pixel(7, 7), 0u);  // the fan's inner edges stay hidden too
}

TEST(PolygonMode, FrontAndBackModesAreSeparate) {
    PipelineFixture f(32, 32);
    f.state.polygonFront = PolygonMode::Fill;
    f.state.polygonBack = PolygonMode::Point;
    // Counter-clockwise (front, filled), then clockwise (back, three points).
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(10, 2), f.windowVertex(2, 10)});
    const int filled = f.coveredPixels();
    EXPECT_GT(filled, 20);
    f.draw(PrimitiveMode::Triangles,
           {f.windowVertex(20.5f, 20.5f), f.windowVertex(20.5f, 28.5f), f.windowVertex(28.5f, 20.5f)});
    EXPECT_EQ(f.coveredPixels(), filled + 3);
}

TEST(PolygonMode, ZeroAreaTriangleIsBackWhenCullingElseClockwise) {
    // Measured: front LINE, back POINT; a degenerate triangle draws lines (17 pixels) or points.
    const auto draw = [](bool frontCCW, bool cull, Face cullFace) {
        PipelineFixture f(32, 32);
        f.state.polygonFront = PolygonMode::Line;
        f.state.polygonBack = PolygonMode::Point;
        f.state.frontFaceCCW = frontCCW;
        f.state.cullEnabled = cull;
        f.state.cullFace = cullFace;
        f.draw(PrimitiveMode::Triangles,
               {f.windowVertex(20.5f, 12.5f), f.windowVertex(4.5f, 4.5f), f.windowVertex(12.5f, 8.5f)});
        return f.coveredPixels();
    };
    EXPECT_EQ(draw(false, false, Face::Back), 17);
    EXPECT_EQ(draw(true, false, Face::Back), 3);
    EXPECT_EQ(draw(false, true, Face::Front), 3);
    EXPECT_EQ(draw(true, true, Face::Front), 3);
    EXPECT_EQ(draw(false, true, Face::Back), 0);
}

TEST(PolygonMode, CullingCountsUnfilledTriangles) {
    PipelineFixture f(32, 32);
    f.state.polygonFront = f.state.polygonBack = PolygonMode::Line;
    f.state.cullEnabled = true;
    f.draw(PrimitiveMode::Triangles, {f.windowVertex(2, 2), f.windowVertex(10, 2), f.windowVertex(2, 10),
                                      f.windowVertex(2, 2), f.windowVertex(2, 10), f.windowVertex(10, 2)});
    EXPECT_EQ(f.pipeline.stats().triangles, 2u);
    EXPECT_EQ(f.pipeline.stats().culledBack, 1u);
    EXPECT_EQ(f.pipeline.stats().rasterized, 1u);
}

TEST(BadInput, NonFiniteAndHugeCoordinatesDrawNothingAndStayInBounds) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (PrimitiveMode mode : {PrimitiveMode::Points, PrimitiveMode::Lines, PrimitiveMode::LineLoop}) {
        PipelineFixture f(8, 8);
        f.state.lineWidth = 200;
        f.state.pointSize = 1e30f;
        f.state.polygonFront = PolygonMode::Line;
        for (float bad : {nan, inf, -inf, 1e30f, 1e-30f}) {
            f.draw(mode, {{{bad, 0, 0, 1}, {1, 1, 1, 1}},
                          {{0, bad, 0, bad}, {1, 1, 1, 1}},
                          {{0.5f, 0.5f, 0, 1}, {nan, 1, 1, 1}},
                          {{bad, bad, bad, bad}, {1, 1, 1, 1}}});
            f.draw(
                PrimitiveMode::Triangles,
                {{{bad, 0, 0, 1}, {1, 1, 1, 1}}, {{0, 0.5f, 0, 1}, {1, 1, 1, 1}}, {{0.5f, 0, 0, bad}, {1, 1, 1, 1}}});
        }
        SUCCEED();
    }
}
