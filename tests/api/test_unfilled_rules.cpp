// Polygons drawn as lines or points go through the reference's draw module, whose stages have
// rules of their own (docs/reference-rules.md, "Unfilled polygons"). Each test draws random
// triangles under the state that brings a rule into play, on MyGL and on OSMesa, and compares
// every pixel's colour and depth. The differential fuzzer found all three.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <random>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 48, kHeight = 40;

// Triangles of both facings, some crossing the view volume's far plane and a user clip plane.
void drawTriangles(unsigned seed, int edgeFlagInside) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> xy(-1.2f, 1.2f), z(-1.3f, 1.3f);
    glBegin(GL_TRIANGLES);
    if (edgeFlagInside >= 0) glEdgeFlag(static_cast<GLboolean>(edgeFlagInside));
    for (int i = 0; i < 3 * 10; ++i) {
        glColor3f(0.2f + 0.1f * static_cast<float>(i % 7), 0.9f - 0.1f * static_cast<float>(i % 5), 0.5f);
        glVertex3f(xy(random), xy(random), z(random));
    }
    glEnd();
}

void clearWithDepth() {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glPointSize(2);
}

void cutByAPlane() {
    const GLdouble plane[] = {0.3, 1.0, 0.0, 0.1};
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
}

constexpr GLenum kModes[] = {GL_POINT, GL_LINE, GL_FILL};

std::string modeName(GLenum mode) { return mode == GL_POINT ? "point" : mode == GL_LINE ? "line" : "fill"; }

}  // namespace

// With no edge flag of their own in the vertices and the current edge flag false, the reference
// culls every face drawn as lines or points (Mesa's _PolygonModeAlwaysCulls), even the edges
// that a user clip plane makes and would draw; an edge flag given inside the block keeps them.
TEST(UnfilledRules, AFalseCurrentEdgeFlagCullsTheUnfilledFaces) {
    for (GLenum front : kModes) {
        for (GLenum back : kModes) {
            for (int edgeFlagInside : {-1, 0, 1}) {
                const auto frames = onBothBackends<Frame>(
                    [&] {
                        clearWithDepth();
                        cutByAPlane();
                        glPolygonMode(GL_FRONT, front);
                        glPolygonMode(GL_BACK, back);
                        glEdgeFlag(GL_FALSE);  // the current flag, before the block
                        drawTriangles(7, edgeFlagInside);
                        return readFrame(kWidth, kHeight);
                    },
                    kWidth, kHeight);
                EXPECT_EQ(frames.mygl, frames.osmesa) << "front " << modeName(front) << ", back " << modeName(back)
                                                      << ", edge flag inside the block " << edgeFlagInside;
            }
        }
    }
}

// The draw module's offset stage is there when any offset mode is on; it decides by the draw's
// first triangle's mode whether to offset, then offsets every triangle alike, by nothing (0 times
// a slope) when it decided not to: a vertex at w = 0 makes the slope infinite, the depth NaN, 0.
// (Not yet reproduced, so not here: filled faces that the draw module draws, beside unfilled
// ones or under a line or point offset, take its per-vertex offset (docs/reference-rules.md).)
TEST(UnfilledRules, TheOffsetStageDecidesAtTheDrawsFirstTriangle) {
    const GLenum enables[] = {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT};
    const GLenum unfilled[] = {GL_POINT, GL_LINE};
    for (GLenum enable : enables) {
        for (GLenum front : unfilled) {
            for (GLenum back : unfilled) {
                const auto frames = onBothBackends<Frame>(
                    [&] {
                        clearWithDepth();
                        glDepthFunc(GL_LEQUAL);
                        glPolygonMode(GL_FRONT, front);
                        glPolygonMode(GL_BACK, back);
                        drawTriangles(11, -1);
                        glEnable(enable);
                        glPolygonOffset(-2.0f, -40.0f);
                        glColor3f(1, 1, 1);
                        drawTriangles(11, -1);
                        return readFrame(kWidth, kHeight);
                    },
                    kWidth, kHeight);
                EXPECT_EQ(frames.mygl, frames.osmesa) << "enable 0x" << std::hex << enable << std::dec << ", front "
                                                      << modeName(front) << ", back " << modeName(back);
            }
        }
    }
    // Points of a strip through w = 0 (infinite slopes) under an offset of the filled mode only.
    const auto frames = onBothBackends<Frame>(
        [&] {
            clearWithDepth();
            glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glBegin(GL_TRIANGLE_STRIP);
            glVertex4d(0.0, 0.0, 1.4170115730883901, 1.4165638563508203);
            glVertex4d(0.0, 0.0, 1.0, 1.0);
            glVertex4d(1.0, 0.0, 0.0, 0.0);
            glEnd();
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_EQ(frames.mygl, frames.osmesa) << "points through w = 0";
}

// With two-sided lighting, the draw module's two-sided stage gives a triangle facing back (by its
// determinant) the back colours, for its lines and points and for a filled face among unfilled ones.
TEST(UnfilledRules, TwoSidedColoursInUnfilledDraws) {
    for (GLenum front : kModes) {
        for (GLenum back : kModes) {
            const auto frames = onBothBackends<Frame>(
                [&] {
                    clearWithDepth();
                    const GLfloat backDiffuse[] = {0.0f, 0.5f, 1.0f, 1.0f}, frontDiffuse[] = {1.0f, 0.5f, 0.0f, 1.0f};
                    glMaterialfv(GL_BACK, GL_DIFFUSE, backDiffuse);
                    glMaterialfv(GL_FRONT, GL_DIFFUSE, frontDiffuse);
                    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                    glEnable(GL_LIGHTING);
                    glEnable(GL_LIGHT0);
                    glPolygonMode(GL_FRONT, front);
                    glPolygonMode(GL_BACK, back);
                    glNormal3f(0.3f, 0.2f, -0.9f);
                    cutByAPlane();
                    drawTriangles(5, -1);
                    return readFrame(kWidth, kHeight);
                },
                kWidth, kHeight);
            EXPECT_EQ(frames.mygl, frames.osmesa) << "front " << modeName(front) << ", back " << modeName(back);
        }
    }
}
