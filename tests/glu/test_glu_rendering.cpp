// Quadrics and tessellated polygons drawn through the same GLU calls on MyGL and on OSMesa: the
// frames must be identical (flat colours, no lighting: triangles, lines and points match the
// reference bit for bit, DESIGN.md 4). Each MyGL frame is written as a PNG beside the test.
#include <gtest/gtest.h>

#include <mygl/glu.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <reference/compare.h>
#include <reference/image.h>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

constexpr int kSize = 96;

void expectSameFrames(const std::string& name, const std::function<void()>& draw) {
    const auto frames = onBothBackends<std::vector<std::uint8_t>>(
        [&] {
            glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            draw();
            std::vector<std::uint8_t> rgba(kSize * kSize * 4);
            glFinish();
            glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
            return rgba;
        },
        kSize, kSize);
    const reference::Image ours{kSize, kSize, frames.mygl}, theirs{kSize, kSize, frames.osmesa};
    reference::writePng("glu-" + name + ".png", ours);
    const reference::Comparison c = reference::compareImages(ours, theirs);
    if (c.differing != 0) reference::writePng("glu-" + name + "-diff.png", reference::diffImage(ours, theirs));
    EXPECT_EQ(c.differing, 0) << name << ": " << reference::toString(c);
    long long background = 0;
    for (int p = 0; p < kSize * kSize; ++p) background += frames.mygl[p * 4] == frames.mygl[0] ? 1 : 0;
    EXPECT_LT(background, kSize * kSize) << name << " drew nothing";
}

void perspectiveView() {
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, 1.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, -3.0, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

struct QuadricCase {
    const char* name;
    GLenum style;
    GLenum orientation;
    bool texture;
};

const QuadricCase kQuadricCases[] = {
    {"fill", GLU_FILL, GLU_OUTSIDE, false},
    {"fill-inside", GLU_FILL, GLU_INSIDE, false},
    {"fill-textured", GLU_FILL, GLU_OUTSIDE, true},
    {"line", GLU_LINE, GLU_OUTSIDE, false},
    {"silhouette", GLU_SILHOUETTE, GLU_OUTSIDE, false},
    {"point", GLU_POINT, GLU_OUTSIDE, false},
};

TEST(GluRendering, QuadricsMatchTheReference) {
    for (const QuadricCase& q : kQuadricCases) {
        for (const GLenum normals : {GLU_SMOOTH, GLU_FLAT}) {
            expectSameFrames(std::string("quadrics-") + q.name + (normals == GLU_FLAT ? "-flat" : ""), [&] {
                perspectiveView();
                glEnable(GL_CULL_FACE);  // inside-out shapes show their far half
                GLUquadric* quadric = gluNewQuadric();
                gluQuadricDrawStyle(quadric, q.style);
                gluQuadricOrientation(quadric, q.orientation);
                gluQuadricNormals(quadric, normals);
                gluQuadricTexture(quadric, q.texture ? GL_TRUE : GL_FALSE);
                glColor3f(0.9f, 0.3f, 0.2f);
                glPushMatrix();
                glTranslatef(-1.0f, 0.6f, 0.0f);
                gluSphere(quadric, 0.7, 14, 9);
                glPopMatrix();
                glColor3f(0.2f, 0.8f, 0.3f);
                glPushMatrix();
                glTranslatef(1.0f, 0.6f, -0.5f);
                gluCylinder(quadric, 0.5, 0.2, 1.0, 12, 3);
                glPopMatrix();
                glColor3f(0.3f, 0.5f, 1.0f);
                glPushMatrix();
                glTranslatef(-1.0f, -0.9f, 0.0f);
                gluDisk(quadric, 0.0, 0.6, 10, 3);
                glTranslatef(2.0f, 0.0f, 0.0f);
                glColor3f(1.0f, 0.9f, 0.2f);
                gluPartialDisk(quadric, 0.25, 0.65, 9, 2, 30.0, -250.0);
                glPopMatrix();
                gluDeleteQuadric(quadric);
            });
        }
    }
}

// GLU's documented primitive modes: a sphere is two triangle fans and stacks - 2 quad strips,
// (all quad strips with texture coordinates); a cylinder one quad strip per stack; a disk with no
// hole a fan and loops - 1 strips.
TEST(GluRendering, QuadricsUseGlusPrimitiveModes) {
    mygl::Context context(16, 16);
    context.makeCurrent();
    GLUquadric* quadric = gluNewQuadric();
    auto countModes = [&](const std::function<void()>& draw) {
        glFinish();
        const mygl::Stats before = context.stats();
        draw();
        glFinish();
        const mygl::Stats after = context.stats();
        std::vector<std::uint64_t> counts;
        for (std::size_t m = 0; m < after.primitivesByMode.size(); ++m)
            counts.push_back(after.primitivesByMode[m] - before.primitivesByMode[m]);
        return counts;
    };
    auto expected = [](std::initializer_list<std::pair<GLenum, std::uint64_t>> modes) {
        std::vector<std::uint64_t> counts(mygl::Stats{}.primitivesByMode.size(), 0);
        for (const auto& [mode, count] : modes) counts[mode] = count;
        return counts;
    };
    EXPECT_EQ(countModes([&] { gluSphere(quadric, 1.0, 8, 6); }), expected({{GL_TRIANGLE_FAN, 2}, {GL_QUAD_STRIP, 4}}));
    EXPECT_EQ(countModes([&] { gluCylinder(quadric, 1.0, 0.5, 2.0, 8, 5); }), expected({{GL_QUAD_STRIP, 5}}));
    EXPECT_EQ(countModes([&] { gluDisk(quadric, 0.0, 1.0, 8, 3); }),
              expected({{GL_TRIANGLE_FAN, 1}, {GL_QUAD_STRIP, 2}}));
    EXPECT_EQ(countModes([&] { gluPartialDisk(quadric, 0.5, 1.0, 8, 3, 0.0, 90.0); }), expected({{GL_QUAD_STRIP, 3}}));
    gluQuadricTexture(quadric, GL_TRUE);
    EXPECT_EQ(countModes([&] { gluSphere(quadric, 1.0, 8, 6); }), expected({{GL_QUAD_STRIP, 6}}));
    gluQuadricDrawStyle(quadric, GLU_LINE);
    // Latitude circles between the poles and one meridian per slice.
    EXPECT_EQ(countModes([&] { gluSphere(quadric, 1.0, 8, 6); }), expected({{GL_LINE_STRIP, 5 + 8}}));
    gluQuadricDrawStyle(quadric, GLU_POINT);
    EXPECT_EQ(countModes([&] { gluCylinder(quadric, 1.0, 0.5, 2.0, 8, 5); }), expected({{GL_POINTS, 1}}));
    gluDeleteQuadric(quadric);
}

std::vector<GLenum> quadricErrors;
void recordQuadricError(GLenum error) { quadricErrors.push_back(error); }

TEST(GluRendering, BadQuadricArgumentsReportAndDrawNothing) {
    mygl::Context context(16, 16);
    context.makeCurrent();
    GLUquadric* quadric = gluNewQuadric();
    gluQuadricCallback(quadric, GLU_ERROR, reinterpret_cast<_GLUfuncptr>(&recordQuadricError));
    quadricErrors.clear();
    const mygl::Stats before = context.stats();
    gluSphere(quadric, 1.0, 1, 4);
    gluSphere(quadric, std::nan(""), 8, 4);
    gluCylinder(quadric, 1.0, 1.0, 0.0, 8, 0);
    gluCylinder(quadric, 0.0, 0.0, 0.0, 8, 2);  // no surface
    gluDisk(quadric, 2.0, 1.0, 8, 2);           // inner beyond outer
    gluPartialDisk(quadric, 0.0, 1.0, 8, 2, 0.0, std::nan(""));
    gluQuadricDrawStyle(quadric, GL_TRIANGLES);
    gluQuadricNormals(quadric, GLU_OUTSIDE);
    gluQuadricOrientation(quadric, GLU_FLAT);
    gluQuadricCallback(quadric, GLU_TESS_BEGIN, nullptr);
    glFinish();
    EXPECT_EQ(context.stats().vertices, before.vertices);
    const std::vector<GLenum> expected{GLU_INVALID_VALUE, GLU_INVALID_VALUE, GLU_INVALID_VALUE, GLU_INVALID_VALUE,
                                       GLU_INVALID_VALUE, GLU_INVALID_VALUE, GLU_INVALID_ENUM,  GLU_INVALID_ENUM,
                                       GLU_INVALID_ENUM,  GLU_INVALID_ENUM};
    EXPECT_EQ(quadricErrors, expected);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    gluDeleteQuadric(quadric);
    gluDeleteQuadric(nullptr);
    gluSphere(nullptr, 1.0, 8, 8);
}

void combine(GLdouble coords[3], void* [4], GLfloat[4], void** out, void* storage) {
    auto& points = *static_cast<std::vector<std::vector<GLdouble>>*>(storage);
    points.push_back({coords[0], coords[1], coords[2]});
    *out = points.back().data();
}

// A concave star with a star-shaped hole and a self-intersecting pentagram, drawn through
// glBegin/glVertex3dv/glEnd as course programs register them.
TEST(GluRendering, TessellatedPolygonsMatchTheReference) {
    for (const GLenum rule : {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE}) {
        for (const bool outline : {false, true}) {
            const std::string name =
                "tess-" + std::to_string(rule - GLU_TESS_WINDING_ODD) + (outline ? "-outline" : "");
            expectSameFrames(name, [&] {
                glMatrixMode(GL_PROJECTION);
                glLoadIdentity();
                gluOrtho2D(-2.0, 2.0, -2.0, 2.0);
                GLUtesselator* tess = gluNewTess();
                // After the context is current: glBegin is the current table's entry.
                gluTessCallback(tess, GLU_TESS_BEGIN, reinterpret_cast<_GLUfuncptr>(glBegin));
                gluTessCallback(tess, GLU_TESS_VERTEX, reinterpret_cast<_GLUfuncptr>(glVertex3dv));
                gluTessCallback(tess, GLU_TESS_END, reinterpret_cast<_GLUfuncptr>(glEnd));
                gluTessCallback(tess, GLU_TESS_COMBINE_DATA, reinterpret_cast<_GLUfuncptr>(&combine));
                gluTessProperty(tess, GLU_TESS_WINDING_RULE, rule);
                gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, outline ? GL_TRUE : GL_FALSE);
                std::vector<std::vector<GLdouble>> points;
                points.reserve(1000);  // combine keeps pointers into it
                auto contour = [&](int count, double cx, double cy, double r1, double r2, double turn) {
                    gluTessBeginContour(tess);
                    for (int k = 0; k < count; ++k) {
                        const double angle = turn * 2 * M_PI * k / count, r = k % 2 ? r2 : r1;
                        points.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle), 0.0});
                        gluTessVertex(tess, points.back().data(), points.back().data());
                    }
                    gluTessEndContour(tess);
                };
                glColor3f(0.9f, 0.7f, 0.2f);
                gluTessBeginPolygon(tess, &points);
                contour(10, -0.9, 0.9, 1.0, 0.45, 1.0);   // star
                contour(10, -0.9, 0.9, 0.35, 0.2, -1.0);  // star-shaped hole
                gluTessEndPolygon(tess);
                glColor3f(0.3f, 0.6f, 1.0f);
                gluTessBeginPolygon(tess, &points);
                contour(5, 0.9, -0.8, 1.0, 1.0, 2.0);  // pentagram: every vertex two steps on
                contour(4, 0.9, -0.8, 0.3, 0.3, 1.0);  // a square over its centre
                gluTessEndPolygon(tess);
                gluDeleteTess(tess);
            });
        }
    }
}

}  // namespace
