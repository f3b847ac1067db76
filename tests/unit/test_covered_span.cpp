// coveredSpan and NarrowRows against their definition: the pixels of the row whose centers pass
// all three edge functions, over random triangles from tiny to huge, on areas narrow enough for
// the per-pixel search and wide enough for the divisions, odd and even rows.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "raster_span.h"
#include "raster_triangle.h"

using namespace glrenderer;

namespace {

bool covers(const RasterTriangle& t, int x, int row) {
    return (t.edges[0].at(x, row) | t.edges[1].at(x, row) | t.edges[2].at(x, row)) >= 0;
}

// The covered pixels of a row by the pixel tests (contiguous: checked below), empty as {1, 0}.
Span pixelSpan(const RasterTriangle& t, int row, int minX, int maxX) {
    Span span{1, 0};
    for (int x = minX; x <= maxX; ++x) {
        if (!covers(t, x, row)) continue;
        if (span.begin > span.end) span.begin = x;
        span.end = x;
    }
    return span;
}

// A walk of `rows` (NarrowRows, SteppedRows) down `count` rows of the area [minX, maxX] from
// `top`, against the pixel tests. Returns the rows walked.
template <class Rows>
int expectWalkMatchesPixelTests(const char* name, Rows rows, const RasterTriangle& t, int minX, int maxX, int top,
                                int count) {
    for (int row = top; row < top + count; ++row) {
        const Span expected = pixelSpan(t, row, minX, maxX), span = rows.next();
        EXPECT_TRUE(expected.begin > expected.end ? span.begin > span.end
                                                  : span.begin == expected.begin && span.end == expected.end)
            << name << " row " << row << " [" << minX << ", " << maxX << "] gives [" << span.begin << ", " << span.end
            << "], pixels [" << expected.begin << ", " << expected.end << "]";
    }
    return count;
}

// Triangles with vertices up to `reach` fixed-point units (1/256 pixel) from a center up to
// `reach` from the origin, in either winding; rows and areas around them.
void expectSpansMatchPixelTests(std::int64_t reach, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_int_distribution<std::int64_t> offset(-reach, reach);
    std::uniform_int_distribution<int> width(-1, 12), pick(0, 7);
    int compared = 0, nonEmpty = 0, walked = 0;
    for (int i = 0; i < 4000; ++i) {
        const std::int64_t cx = offset(random), cy = offset(random);
        FixedPoint p[3];
        for (FixedPoint& v : p) v = {cx + offset(random), cy + offset(random)};
        RasterTriangle t;
        const bool flip = pick(random) < 4;
        const FixedPoint& b = flip ? p[2] : p[1];
        const FixedPoint& c = flip ? p[1] : p[2];
        t.edges[0] = EdgeFunction(p[0], b), t.edges[1] = EdgeFunction(b, c), t.edges[2] = EdgeFunction(c, p[0]);
        const auto pixelNear = [&](std::int64_t fixed) {
            return static_cast<int>((fixed >> kSubpixelBits) + pick(random) - 3);
        };
        // NarrowRows down the rows of an area up to its width from above the first vertex.
        for (int j = 0; j < 4; ++j) {
            const FixedPoint& corner = p[static_cast<std::size_t>(j % 3)];
            const int minX = pixelNear(corner.x) - pick(random) / 2, top = pixelNear(corner.y) - 3;
            if (j % 2 == 0) {
                const int maxX = minX + pick(random) % 4;
                walked += expectWalkMatchesPixelTests("NarrowRows<4>", NarrowRows<4>(t, minX, maxX, top), t, minX, maxX,
                                                      top, 10);
            } else {
                const int maxX = minX + pick(random) % 8;
                walked += expectWalkMatchesPixelTests("NarrowRows<8>", NarrowRows<8>(t, minX, maxX, top), t, minX, maxX,
                                                      top, 10);
            }
            if (j == 0) {
                const int left = minX - pick(random) * 5, right = minX + 40 + pick(random) * 9;
                expectWalkMatchesPixelTests("SteppedRows", SteppedRows(t, left, right, top - 8), t, left, right,
                                            top - 8, 40);
            }
        }
        for (int j = 0; j < 24; ++j) {
            const FixedPoint& corner = p[static_cast<std::size_t>(j % 3)];
            const int row = pixelNear(corner.y);
            const int minX = pixelNear(corner.x) - pick(random);
            const int maxX = minX + (j % 4 == 0 ? 40 + pick(random) * 9 : width(random));  // both searches
            bool found = false;
            int first = 0, last = 0;
            for (int x = minX; x <= maxX; ++x) {
                if (!covers(t, x, row)) continue;
                ASSERT_TRUE(!found || last == x - 1) << "covered pixels not contiguous";
                if (!found) first = x, found = true;
                last = x;
            }
            const Span span = coveredSpan(t, row, minX, maxX);
            ++compared;
            if (!found) {
                EXPECT_GT(span.begin, span.end) << "row " << row << " [" << minX << ", " << maxX << "]";
                continue;
            }
            ++nonEmpty;
            EXPECT_EQ(span.begin, first) << "row " << row << " [" << minX << ", " << maxX << "]";
            EXPECT_EQ(span.end, last) << "row " << row << " [" << minX << ", " << maxX << "]";
        }
    }
    EXPECT_GT(nonEmpty, compared / 20);  // the cases reach covered pixels, not only empty rows
    EXPECT_GT(walked, 100000);
}

}  // namespace

TEST(CoveredSpan, SmallTrianglesMatchThePixelTests) { expectSpansMatchPixelTests(4 * 256, 1); }

TEST(CoveredSpan, MeshSizedTrianglesMatchThePixelTests) { expectSpansMatchPixelTests(40 * 256, 2); }

// Up to 2^19 pixels from the origin (the edge values stay within 64 bits).
TEST(CoveredSpan, HugeTrianglesAndSliversMatchThePixelTests) { expectSpansMatchPixelTests(std::int64_t{1} << 27, 3); }
