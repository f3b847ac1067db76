// Triangles of less than a pixel's area whose bounds hold a few pixel centers: setup drops those
// that cover no center before their planes (PixelCenterTest). Their pixels must be the
// reference's, a center exactly on an edge of every kind included (left, right, top and bottom
// edges, sloped ones, a vertex on the center), in both windings, with bounds cut by a scissor,
// and with the exact method tested pixel by pixel; the counters still count every such triangle
// as rasterized.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "backends.h"

namespace {

constexpr int kSize = 160, kCell = 6;  // each triangle alone in its cell, around a pixel center
constexpr int kCellsAcross = kSize / kCell;

struct Point {
    float x, y;  // from the cell's pixel center, in pixels (multiples of 1/16: exact in window)
};
using Triangle = std::array<Point, 3>;

double twiceArea(const Triangle& t) {
    return (t[1].x - t[0].x) * static_cast<double>(t[2].y - t[0].y) -
           (t[1].y - t[0].y) * static_cast<double>(t[2].x - t[0].x);
}

// Directions of edges through the center, as multiples of 1/16 pixel.
constexpr std::array<Point, 8> kDirections = {{{0, 4}, {4, 0}, {4, 4}, {4, -4}, {2, 4}, {4, 2}, {-2, 4}, {4, -2}}};

std::vector<Triangle> tinyTriangles() {
    std::vector<Triangle> triangles;
    const auto add = [&](Triangle t) {
        if (twiceArea(t) == 0) return;
        for (Point& p : t) p.x /= 16, p.y /= 16;
        triangles.push_back(t);
        triangles.push_back({t[1], t[0], t[2]});  // the other winding
    };
    // An edge through the center, the third vertex on either side: the center is on a left,
    // right, top or bottom edge, or a sloped one.
    for (const Point& d : kDirections) {
        for (const float side : {-1.0f, 1.0f}) {
            const Point normal{-d.y * side * 2, d.x * side * 2};
            add({Point{-d.x, -d.y}, Point{d.x * 1.5f, d.y * 1.5f}, Point{normal.x + d.x / 4, normal.y + d.y / 4}});
        }
    }
    // A vertex on the center, the triangle opening in each direction.
    for (std::size_t k = 0; k < kDirections.size(); ++k) {
        const Point& a = kDirections[k];
        const Point& b = kDirections[(k + 3) % kDirections.size()];
        add({Point{0, 0}, Point{a.x * 2, a.y * 2}, Point{b.x * 2, b.y * 2}});
    }
    // Random small ones on the 1/16 grid, which puts many edges through centers, and slivers up
    // to three pixels long.
    std::mt19937 random(7);
    std::uniform_int_distribution<int> small(-16, 16), along(-28, 28), across(-3, 3);
    while (triangles.size() < 500) {
        add({Point{float(small(random)), float(small(random))}, Point{float(small(random)), float(small(random))},
             Point{float(small(random)), float(small(random))}});
        const int a = along(random), b = along(random), c = across(random), d = across(random);
        add({Point{float(a), float(c)}, Point{float(b), float(d)}, Point{float(a + b) / 2, float(c + d + 1) / 2}});
        add({Point{float(c), float(a)}, Point{float(d), float(b)}, Point{float(c - d + 1) / 2, float(a - b) / 2}});
    }
    return triangles;
}

// Draws triangle i around the center of the middle pixel of cell i, one glBegin for all, over
// the whole window cleared, with `scissor` only a part of it.
void drawInCells(const std::vector<Triangle>& triangles, bool scissor) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    if (scissor) glScissor(17, 23, 101, 89), glEnable(GL_SCISSOR_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kSize, 0, kSize, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLES);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const float cx = static_cast<float>(i % kCellsAcross * kCell) + 3.5f;
        const float cy = static_cast<float>(i / kCellsAcross * kCell) + 3.5f;
        for (const Point& p : triangles[i]) glVertex2f(cx + p.x, cy + p.y);
    }
    glEnd();
}

struct Drawn {
    std::vector<std::uint8_t> pixels;
    mygl::Stats stats;
};

Drawn drawWithMygl(const std::vector<Triangle>& triangles, glrenderer::RasterMethod method, bool scissor) {
    mygl::Context context(kSize, kSize);
    context.makeCurrent();
    context.setMethods({method});
    drawInCells(triangles, scissor);
    Drawn drawn;
    drawn.pixels = context.readPixels();
    drawn.stats = context.stats();
    return drawn;
}

std::vector<std::uint8_t> drawWithOsmesa(const std::vector<Triangle>& triangles, bool scissor) {
    reference::OsmesaContext context(kSize, kSize);
    context.makeCurrent();
    drawInCells(triangles, scissor);
    return context.readPixels();
}

// The triangles whose cell has a lit pixel in `pixels`.
std::vector<bool> coveringTriangles(const std::vector<std::uint8_t>& pixels, std::size_t count) {
    std::vector<bool> covering(count, false);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const std::size_t cell = static_cast<std::size_t>(y / kCell * kCellsAcross + x / kCell);
            if (pixels[static_cast<std::size_t>(y * kSize + x) * 4] != 0 && cell < count) covering[cell] = true;
        }
    }
    return covering;
}

}  // namespace

TEST(TinyTriangles, CoverTheReferencesCentersAndCountAsRasterized) {
    const std::vector<Triangle> triangles = tinyTriangles();
    ASSERT_LE(triangles.size(), static_cast<std::size_t>(kCellsAcross * kCellsAcross));
    for (const bool scissor : {false, true}) {
        const std::vector<std::uint8_t> theirs = drawWithOsmesa(triangles, scissor);
        std::uint64_t litPixels = 0;
        for (std::size_t i = 0; i < theirs.size(); i += 4) litPixels += theirs[i] != 0;
        // The case covers both outcomes among triangles of less than a pixel's area.
        const std::vector<bool> covering = coveringTriangles(theirs, triangles.size());
        int smallCovering = 0, smallEmpty = 0;
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            if (std::abs(twiceArea(triangles[i])) < 2.0) ++(covering[i] ? smallCovering : smallEmpty);
        }
        if (!scissor) {
            EXPECT_GE(smallCovering, 80);
            EXPECT_GE(smallEmpty, 80);
        }
        for (const glrenderer::RasterMethod method :
             {glrenderer::RasterMethod::Exact, glrenderer::RasterMethod::ExactPerPixel}) {
            const Drawn ours = drawWithMygl(triangles, method, scissor);
            const std::vector<bool> oursCovering = coveringTriangles(ours.pixels, triangles.size());
            for (std::size_t i = 0; i < triangles.size(); ++i) {
                EXPECT_EQ(oursCovering[i], covering[i]) << "triangle " << i << " scissor " << scissor;
            }
            EXPECT_EQ(ours.pixels, theirs) << "scissor " << scissor;
            EXPECT_EQ(ours.stats.triangles, triangles.size());
            EXPECT_EQ(ours.stats.rasterized, triangles.size());  // none has zero area
            EXPECT_EQ(ours.stats.fragments, litPixels);
            EXPECT_EQ(ours.stats.fragmentsPassed, litPixels);
        }
    }
}
