// Properties of the GLU tessellator that can fail: for random concave, holed and self-intersecting
// polygons under every winding rule, the triangles cover exactly the points the rule keeps, once
// each; crossings go through the combine callback; boundaries and edge flags trace the same
// region; misuse and non-finite input report errors and never crash or hang.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <limits>
#include <random>
#include <string>

#include "tess_recorder.h"

using testing_support::Point3;
using testing_support::TessRecorder;

namespace {

using Contour = std::vector<Point3>;

const GLenum kRules[] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
                         GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO};

bool ruleKeeps(GLenum rule, int winding) {
    switch (rule) {
    case GLU_TESS_WINDING_ODD: return winding % 2 != 0;
    case GLU_TESS_WINDING_NONZERO: return winding != 0;
    case GLU_TESS_WINDING_POSITIVE: return winding > 0;
    case GLU_TESS_WINDING_NEGATIVE: return winding < 0;
    default: return std::abs(winding) >= 2;
    }
}

double cross(const Point3& a, const Point3& b, double x, double y) {
    return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
}

// The winding number of (x, y) around the contours, counted independently of the tessellator.
int windingNumber(const std::vector<Contour>& contours, double x, double y) {
    int winding = 0;
    for (const Contour& c : contours) {
        for (std::size_t k = 0; k < c.size(); ++k) {
            const Point3 &a = c[k], &b = c[(k + 1) % c.size()];
            if (a[1] <= y && b[1] > y && cross(a, b, x, y) > 0) ++winding;
            if (b[1] <= y && a[1] > y && cross(a, b, x, y) < 0) --winding;
        }
    }
    return winding;
}

double distanceToSegment(const Point3& a, const Point3& b, double x, double y) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length2 = dx * dx + dy * dy;
    double t = length2 > 0 ? ((x - a[0]) * dx + (y - a[1]) * dy) / length2 : 0.0;
    t = std::fmax(0.0, std::fmin(1.0, t));
    return std::hypot(x - (a[0] + t * dx), y - (a[1] + t * dy));
}

void tessellate(GLUtesselator* tess, TessRecorder& recorder, const std::vector<Contour>& contours) {
    gluTessBeginPolygon(tess, &recorder);
    for (const Contour& contour : contours) {
        gluTessBeginContour(tess);
        for (const Point3& p : contour) {
            Point3* kept = recorder.keep(p);
            gluTessVertex(tess, kept->data(), kept);
        }
        gluTessEndContour(tess);
    }
    gluTessEndPolygon(tess);
}

using Triangle = std::array<Point3, 3>;

std::vector<Triangle> triangles(const TessRecorder& recorder) {
    std::vector<Triangle> result;
    for (const auto& primitive : recorder.primitives) {
        EXPECT_EQ(primitive.mode, static_cast<GLenum>(GL_TRIANGLES));
        EXPECT_EQ(primitive.vertices.size() % 3, 0u);
        for (std::size_t k = 0; k + 2 < primitive.vertices.size(); k += 3) {
            result.push_back({*primitive.vertices[k], *primitive.vertices[k + 1], *primitive.vertices[k + 2]});
        }
    }
    return result;
}

Contour randomContour(std::mt19937& random, int count, double radius, double cx, double cy) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Contour c;
    for (int k = 0; k < count; ++k) c.push_back({cx + radius * unit(random), cy + radius * unit(random), 0.0});
    return c;
}

// A star-shaped concave contour (no self-crossing), counter-clockwise unless `reversed`.
Contour starContour(std::mt19937& random, int count, double inner, double outer, bool reversed) {
    std::uniform_real_distribution<double> radius(inner, outer);
    Contour c;
    for (int k = 0; k < count; ++k) {
        const double angle = 2 * M_PI * k / count * (reversed ? -1 : 1);
        const double r = radius(random);
        c.push_back({r * std::cos(angle), r * std::sin(angle), 0.0});
    }
    return c;
}

// The polygons of the property tests: concave, with holes, self-intersecting, overlapping.
std::vector<std::vector<Contour>> polygons() {
    std::mt19937 random(1234);
    std::vector<std::vector<Contour>> result;
    for (int k = 0; k < 6; ++k) result.push_back({starContour(random, 7 + 3 * k, 0.3, 1.0, k % 2 == 1)});
    for (int k = 0; k < 6; ++k) {
        result.push_back({starContour(random, 9 + k, 0.7, 1.0, false), starContour(random, 5 + k, 0.2, 0.5, true)});
    }
    for (int k = 0; k < 10; ++k) result.push_back({randomContour(random, 5 + k, 1.0, 0, 0)});
    for (int k = 0; k < 6; ++k) {
        result.push_back({randomContour(random, 6, 0.8, -0.2, 0), randomContour(random, 7, 0.8, 0.2, 0.1),
                          starContour(random, 8, 0.3, 0.6, k % 2 == 0)});
    }
    return result;
}

bool insideTriangle(const Triangle& t, double x, double y) {
    const double a = cross(t[0], t[1], x, y), b = cross(t[1], t[2], x, y), c = cross(t[2], t[0], x, y);
    return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
}

class Tessellator : public ::testing::Test {
protected:
    void SetUp() override { tess = gluNewTess(); }
    void TearDown() override { gluDeleteTess(tess); }
    GLUtesselator* tess = nullptr;
};

// Tessellates `contours` under `rule` (windings seen from +z) and checks `samples` random points
// of the box [-extent, extent]^2: each point the rule keeps lies in exactly one triangle, every
// other point in none. Counts the points checked inside and outside.
void expectExactCover(GLUtesselator* tess, const std::vector<Contour>& contours, GLenum rule, std::mt19937& random,
                      int samples, double extent, int counts[2]) {
    gluTessNormal(tess, 0, 0, 1);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, rule);
    TessRecorder recorder(tess);
    tessellate(tess, recorder, contours);
    EXPECT_TRUE(recorder.errors.empty());
    const std::vector<Triangle> tris = triangles(recorder);
    std::uniform_real_distribution<double> sample(-extent, extent);
    for (int s = 0; s < samples; ++s) {
        const double x = sample(random), y = sample(random);
        bool nearEdge = false;
        for (const Contour& c : contours) {
            for (std::size_t k = 0; k < c.size() && !nearEdge; ++k) {
                nearEdge = distanceToSegment(c[k], c[(k + 1) % c.size()], x, y) < 1e-7;
            }
        }
        for (const Triangle& t : tris) {
            for (int k = 0; k < 3 && !nearEdge; ++k) nearEdge = distanceToSegment(t[k], t[(k + 1) % 3], x, y) < 1e-7;
        }
        if (nearEdge) continue;
        int covering = 0;
        for (const Triangle& t : tris) covering += insideTriangle(t, x, y) ? 1 : 0;
        const bool keep = ruleKeeps(rule, windingNumber(contours, x, y));
        ASSERT_EQ(covering, keep ? 1 : 0) << "rule " << rule << " at " << x << ", " << y;
        ++counts[keep ? 1 : 0];
    }
}

TEST_F(Tessellator, TrianglesCoverExactlyWhatEachWindingRuleKeepsOnce) {
    std::mt19937 random(99);
    int counts[2] = {0, 0};
    const auto all = polygons();
    for (const GLenum rule : kRules) {
        for (std::size_t n = 0; n < all.size(); ++n) {
            SCOPED_TRACE("polygon " + std::to_string(n));
            expectExactCover(tess, all[n], rule, random, 1500, 1.2, counts);
        }
    }
    EXPECT_GT(counts[1], 10000);  // inside
    EXPECT_GT(counts[0], 10000);  // outside
}

// Degenerate arrangements: a hole touching the outline at a corner, squares sharing an edge
// (either way round), collinear overlapping edges, repeated vertices, a zero-width spike, a
// vertex lying on another contour's edge.
TEST_F(Tessellator, TouchingOverlappingAndRepeatedFeaturesStillCoverExactly) {
    const std::vector<std::vector<Contour>> cases = {
        {{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 0, 0}, {0.5, 1, 0}, {1, 0.5, 0}}},
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}},
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{1, 1, 0}, {2, 1, 0}, {2, 0, 0}, {1, 0, 0}}},
        {{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {{0.5, 0, 0}, {1.5, 0, 0}, {1.5, -1, 0}, {0.5, -1, 0}}},
        {{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 0}}},
        {{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}, {1, 3, 0}, {1, 2, 0}, {0, 2, 0}}},
        {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 0, 0}, {1, 0, 0}, {0.5, 0.5, 0}}},
        {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}},
    };
    std::mt19937 random(7);
    int counts[2] = {0, 0};
    for (std::size_t n = 0; n < cases.size(); ++n) {
        for (const GLenum rule : kRules) {
            SCOPED_TRACE("case " + std::to_string(n));
            expectExactCover(tess, cases[n], rule, random, 400, 3.2, counts);
        }
    }
    EXPECT_GT(counts[1], 500);  // of 16000 samples over a 6.4 x 6.4 box
}

TEST_F(Tessellator, CombineMakesEveryCrossingOfTwoEdges) {
    // A pentagram: five crossings, each where two of its edges cross.
    Contour star;
    for (int k = 0; k < 5; ++k) {
        const double angle = M_PI / 2 + 4 * M_PI * k / 5;
        star.push_back({std::cos(angle), std::sin(angle), 0.5});
    }
    for (const GLenum rule : {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO}) {
        gluTessProperty(tess, GLU_TESS_WINDING_RULE, rule);
        TessRecorder recorder(tess);
        tessellate(tess, recorder, {star});
        ASSERT_EQ(recorder.combined.size(), 5u);
        for (const Point3& p : recorder.combined) {
            int edgesThrough = 0;
            for (int k = 0; k < 5; ++k)
                edgesThrough += distanceToSegment(star[k], star[(k + 1) % 5], p[0], p[1]) < 1e-12;
            EXPECT_EQ(edgesThrough, 2);
            EXPECT_DOUBLE_EQ(p[2], 0.5);  // combined in object space
        }
        // ODD leaves the centre pentagon out (winding 2), NONZERO fills it: 5 or 5 + 3 triangles.
        EXPECT_EQ(triangles(recorder).size(), rule == GLU_TESS_WINDING_ODD ? 5u : 8u);
    }
}

TEST_F(Tessellator, CrossingWithoutCombineReportsAndDrawsNothing) {
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, nullptr);
    TessRecorder recorder(tess);
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, nullptr);
    const Contour bowtie{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
    tessellate(tess, recorder, {bowtie});
    EXPECT_EQ(recorder.errors, std::vector<GLenum>{GLU_TESS_NEED_COMBINE_CALLBACK});
    EXPECT_TRUE(recorder.primitives.empty());
}

double signedArea(const std::vector<const Point3*>& loop) {
    double area = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const Point3 &a = *loop[k], &b = *loop[(k + 1) % loop.size()];
        area += a[0] * b[1] - b[0] * a[1];
    }
    return area / 2;
}

TEST_F(Tessellator, BoundaryLoopsAndEdgeFlagsTraceTheFilledRegion) {
    gluTessNormal(tess, 0, 0, 1);
    for (const auto& contours : polygons()) {
        gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_NONZERO);
        TessRecorder filled(tess);
        tessellate(tess, filled, contours);
        double fillArea = 0, flaggedLength = 0;
        for (const Triangle& t : triangles(filled)) {
            std::vector<const Point3*> corners{&t[0], &t[1], &t[2]};
            fillArea += signedArea(corners);
        }
        for (const auto& primitive : filled.primitives) {
            for (std::size_t k = 0; k < primitive.vertices.size(); ++k) {
                const Point3& a = *primitive.vertices[k];
                const Point3& b = *primitive.vertices[k % 3 == 2 ? k - 2 : k + 1];
                if (primitive.edgeFlags[k]) flaggedLength += std::hypot(b[0] - a[0], b[1] - a[1]);
            }
        }
        gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
        TessRecorder outline(tess);
        tessellate(tess, outline, contours);
        gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);
        double loopArea = 0, loopLength = 0;
        for (const auto& loop : outline.primitives) {
            EXPECT_EQ(loop.mode, static_cast<GLenum>(GL_LINE_LOOP));
            loopArea += signedArea(loop.vertices);
            for (std::size_t k = 0; k < loop.vertices.size(); ++k) {
                const Point3 &a = *loop.vertices[k], &b = *loop.vertices[(k + 1) % loop.vertices.size()];
                loopLength += std::hypot(b[0] - a[0], b[1] - a[1]);
            }
        }
        EXPECT_GT(fillArea, 0.0);
        EXPECT_NEAR(loopArea, fillArea, 1e-9);  // holes wind clockwise and subtract
        EXPECT_NEAR(flaggedLength, loopLength, 1e-9);
    }
}

TEST_F(Tessellator, TheNormalDecidesWhichWayContoursWind) {
    const Contour clockwise{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
    TessRecorder recorder(tess);
    gluTessNormal(tess, 0, 0, 1);  // seen from +z the square winds -1: nothing is positive
    tessellate(tess, recorder, {clockwise});
    EXPECT_TRUE(recorder.primitives.empty());
    gluTessNormal(tess, 0, 0, -1);
    tessellate(tess, recorder, {clockwise});
    EXPECT_EQ(triangles(recorder).size(), 2u);
    recorder.clear();
    gluTessNormal(tess, 0, 0, 0);  // computed: the polygon's own orientation counts as positive
    tessellate(tess, recorder, {clockwise});
    EXPECT_EQ(triangles(recorder).size(), 2u);
}

// The plain (not _DATA) callbacks, for GLU 1.0's calls which pass no polygon data.
std::vector<const Point3*> plainVertices;
std::vector<GLenum> plainModes, plainErrors;
void plainBegin(GLenum mode) { plainModes.push_back(mode); }
void plainVertex(void* data) { plainVertices.push_back(static_cast<const Point3*>(data)); }
void plainError(GLenum error) { plainErrors.push_back(error); }

void usePlainCallbacks(GLUtesselator* tess) {
    for (GLenum which : {GLU_TESS_BEGIN_DATA, GLU_TESS_VERTEX_DATA, GLU_TESS_END_DATA, GLU_TESS_ERROR_DATA,
                         GLU_TESS_EDGE_FLAG_DATA, GLU_TESS_COMBINE_DATA}) {
        gluTessCallback(tess, which, nullptr);
    }
    gluTessCallback(tess, GLU_TESS_BEGIN, reinterpret_cast<_GLUfuncptr>(&plainBegin));
    gluTessCallback(tess, GLU_TESS_VERTEX, reinterpret_cast<_GLUfuncptr>(&plainVertex));
    gluTessCallback(tess, GLU_TESS_ERROR, reinterpret_cast<_GLUfuncptr>(&plainError));
    plainVertices.clear();
    plainModes.clear();
    plainErrors.clear();
}

TEST_F(Tessellator, OldPolygonCallsWithPlainCallbacksMakeAHole) {
    usePlainCallbacks(tess);
    std::deque<Point3> storage;
    const Contour outer{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}}, inner{{1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
    auto vertex = [&](const Point3& p) {
        Point3& kept = storage.emplace_back(p);
        gluTessVertex(tess, kept.data(), &kept);
    };
    gluBeginPolygon(tess);
    for (const Point3& p : outer) vertex(p);
    gluNextContour(tess, GLU_INTERIOR);
    for (const Point3& p : inner) vertex(p);
    gluEndPolygon(tess);
    EXPECT_EQ(plainModes, std::vector<GLenum>{GL_TRIANGLES});
    ASSERT_EQ(plainVertices.size() % 3, 0u);
    double area = 0;
    for (std::size_t k = 0; k < plainVertices.size(); k += 3) {
        area +=
            cross(*plainVertices[k], *plainVertices[k + 1], (*plainVertices[k + 2])[0], (*plainVertices[k + 2])[1]) / 2;
    }
    EXPECT_DOUBLE_EQ(area, 16.0 - 4.0);  // ODD: the inner square is a hole; triangles counter-clockwise
}

TEST_F(Tessellator, MisuseReportsTheMissingCall) {
    usePlainCallbacks(tess);  // a begin GLU supplies itself has no polygon data
    Point3 p{0, 0, 0};
    gluTessVertex(tess, p.data(), &p);   // no polygon, no contour
    gluTessEndPolygon(tess);             // contour still open
    gluTessEndContour(tess);             // no polygon, no contour (leaves a polygon open)
    gluTessBeginPolygon(tess, nullptr);  // previous polygon unfinished
    gluTessBeginPolygon(tess, nullptr);  // again
    gluTessBeginContour(tess);
    gluTessBeginContour(tess);  // previous contour unfinished
    gluTessProperty(tess, 0x1234, 0);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, 7);
    gluTessProperty(tess, GLU_TESS_TOLERANCE, -1);
    gluTessCallback(tess, 0x1234, nullptr);
    const std::vector<GLenum> expected{GLU_TESS_MISSING_BEGIN_POLYGON,
                                       GLU_TESS_MISSING_BEGIN_CONTOUR,
                                       GLU_TESS_MISSING_END_CONTOUR,
                                       GLU_TESS_MISSING_BEGIN_POLYGON,
                                       GLU_TESS_MISSING_BEGIN_CONTOUR,
                                       GLU_TESS_MISSING_END_POLYGON,
                                       GLU_TESS_MISSING_END_POLYGON,
                                       GLU_TESS_MISSING_END_CONTOUR,
                                       GLU_INVALID_ENUM,
                                       GLU_INVALID_VALUE,
                                       GLU_INVALID_VALUE,
                                       GLU_INVALID_ENUM};
    EXPECT_EQ(plainErrors, expected);
    GLdouble value = 0;
    gluGetTessProperty(tess, GLU_TESS_WINDING_RULE, &value);
    EXPECT_EQ(value, GLU_TESS_WINDING_ODD);
    gluTessProperty(tess, GLU_TESS_TOLERANCE, 0.25);
    gluGetTessProperty(tess, GLU_TESS_TOLERANCE, &value);
    EXPECT_EQ(value, 0.25);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
    EXPECT_EQ(plainErrors.size(), expected.size());
    EXPECT_TRUE(plainModes.empty());  // one vertex is no polygon
}

TEST_F(Tessellator, NonFiniteAndHugeCoordinatesDoNotCrashOrHang) {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    for (const GLenum rule : kRules) {
        gluTessProperty(tess, GLU_TESS_WINDING_RULE, rule);
        TessRecorder recorder(tess);
        tessellate(tess, recorder,
                   {{{0, 0, 0}, {nan, 1, 0}, {1, inf, 0}, {1, 1, 0}, {-inf, 0, nan}, {0, 1, 0}},
                    {{1e300, 1e300, 0}, {-1e300, 1e299, 0}, {1e-300, -1e300, 0}, {0, 0, 0}}});
        EXPECT_GE(recorder.errors.size(), 1u);
        for (GLenum e : recorder.errors) EXPECT_EQ(e, static_cast<GLenum>(GLU_TESS_COORD_TOO_LARGE));
        EXPECT_FALSE(recorder.nestedBegin);
    }
}

TEST_F(Tessellator, DegenerateInputDrawsNothing) {
    TessRecorder recorder(tess);
    tessellate(tess, recorder, {{}, {{1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}});
    EXPECT_TRUE(recorder.primitives.empty());
    EXPECT_TRUE(recorder.errors.empty());
}

}  // namespace
