// Culling of triangles that go through the reference's draw module (here: a vertex behind the
// near plane): its cull stage decides by a float determinant of the clipped triangle's window
// positions, zero counting as back-facing, before setup's fixed-point area decides too
// (issue 12, item 8). Slivers found by random search where the two disagree; each differed
// from OSMesa by a pixel before.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <array>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kSize = 32;

struct Sliver {
    GLenum cullFace, frontFace;
    std::array<std::array<GLfloat, 3>, 3> colors;
    std::array<std::array<GLfloat, 4>, 3> positions;  // clip coordinates
};

const Sliver kSlivers[] = {
    // Setup's area says front, the float determinant back: the reference culls the back face.
    {GL_BACK,
     GL_CCW,
     {{{0x1.30d3ap-1f, 0x1.0cb3dep-1f, 0x1.ab2434p-1f},
       {0x1.b0ba32p-1f, 0x1.3d162ep-2f, 0x1.b15b78p-1f},
       {0x1.6cf164p-2f, 0x1.e2a042p-1f, 0x1.07e448p-2f}}},
     {{{-0x1.ad1ca8p-2f, 0x1.e8478p-2f, 0x1.2b027p+0f, 0x1.010a8p+1f},
       {-0x1.fd0c24p-1f, -0x1.9b19b8p+0f, -0x1.01bd5cp+1f, 0x1.224facp+0f},
       {-0x1.124f64p+0f, -0x1.e2be44p+0f, -0x1.5e26f8p+1f, 0x1.043ddcp+0f}}}},
    {GL_BACK,
     GL_CCW,
     {{{0x1.9cf486p-3f, 0x1.969c94p-1f, 0x1.94c676p-1f},
       {0x1.c72e02p-2f, 0x1.624b36p-2f, 0x1.bb00bep-3f},
       {0x1.cf420ap-4f, 0x1.f0b8dcp-5f, 0x1.ce3b34p-3f}}},
     {{{0x1.68a0ap+0f, 0x1.28a3fcp+0f, -0x1.90d8acp+1f, 0x1.54ec8ap+0f},
       {0x1.446d8p-1f, -0x1.4c62fap+0f, 0x1.9738p-7f, 0x1.d65bb2p+0f},
       {0x1.dfd65p+0f, 0x1.515168p+1f, 0x1.f870fep+0f, 0x1.072878p+0f}}}},
    // A zero determinant is back-facing: with front faces culled the sliver is drawn.
    {GL_FRONT,
     GL_CW,
     {{{0x1.9451e4p-5f, 0x1.62eae2p-1f, 0x1.1cac4cp-4f},
       {0x1.7a4856p-2f, 0x1.ef122ep-1f, 0x1.17612cp-1f},
       {0x1.4eacb6p-1f, 0x1.766854p-1f, 0x1.9961fap-1f}}},
     {{{-0x1.14cfccp+0f, 0x1.e9738p+0f, 0x1.e2e2ep-3f, 0x1.a320dp-4f},
       {0x1.71965p+0f, 0x1.db02cp-4f, 0x1.8523b4p+0f, 0x1.b31912p+0f},
       {0x1.e3d108p+0f, -0x1.9c7a22p-3f, -0x1.d46706p+1f, 0x1.fb5b94p+0f}}}},
    {GL_FRONT,
     GL_CCW,
     {{{0x1.25328p-2f, 0x1.ef4d0ap-1f, 0x1.ff1ec6p-3f},
       {0x1.7cbbe8p-2f, 0x1.e852c6p-1f, 0x1.076366p-1f},
       {0x1.57122ap-1f, 0x1.85f2b2p-2f, 0x1.2b3dd8p-1f}}},
     {{{-0x1.e346c8p+0f, -0x1.1d405p+0f, 0x1.196dd8p+0f, 0x1.83fb9p+0f},
       {0x1.e840fp-2f, 0x1.ba62acp+0f, -0x1.1d0c44p-1f, 0x1.d38526p+0f},
       {0x1.23d8ep+2f, 0x1.a8b97p+2f, -0x1.eea86cp+1f, 0x1.2e6f2cp+1f}}}},
};

}  // namespace

TEST(DrawModuleCulling, ClippedSliversFaceAsTheReferenceDecides) {
    for (const Sliver& sliver : kSlivers) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                glEnable(GL_DEPTH_TEST);
                glEnable(GL_CULL_FACE);
                glCullFace(sliver.cullFace);
                glFrontFace(sliver.frontFace);
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                glBegin(GL_TRIANGLES);
                for (int i = 0; i < 3; ++i) {
                    glColor3fv(sliver.colors[i].data());
                    glVertex4fv(sliver.positions[i].data());
                }
                glEnd();
                return readFrame(kSize, kSize);
            },
            kSize, kSize);
        EXPECT_EQ(frames.mygl, frames.osmesa) << sliver.positions[0][0];
    }
}

TEST(DrawModuleCulling, ACulledFaceTakesTheOtherFacesPolygonMode) {
    // Back-facing quads, filled, with the culled front faces in LINE or POINT mode: the reference
    // draws them as plain filled quads (direct path, v0-v2 diagonal), not through its unfilled
    // stage. Smooth colors and a bent depth show the diagonal.
    for (const GLenum culled : {GL_LINE, GL_POINT}) {
        for (const GLenum face : {GL_FRONT, GL_BACK}) {
            const auto frames = onBothBackends<Frame>(
                [&] {
                    glEnable(GL_DEPTH_TEST);
                    glEnable(GL_CULL_FACE);
                    glCullFace(face);
                    glPolygonMode(face, culled);
                    glPolygonMode(face == GL_FRONT ? GL_BACK : GL_FRONT, GL_FILL);
                    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                    glBegin(GL_QUADS);
                    const GLfloat corners[4][2] = {{-0.9f, -0.8f}, {0.85f, -0.9f}, {0.8f, 0.9f}, {-0.85f, 0.8f}};
                    const GLfloat depths[4] = {0.9f, -0.7f, 0.8f, -0.9f};
                    for (int i = 0; i < 4; ++i) {
                        // Counter-clockwise for a culled back face, clockwise for a culled front face.
                        const int corner = face == GL_BACK ? i : 3 - i;
                        glColor3f(static_cast<GLfloat>(corner % 2), static_cast<GLfloat>(corner / 2),
                                  static_cast<GLfloat>(corner == 1));
                        glVertex3f(corners[corner][0], corners[corner][1], depths[corner]);
                    }
                    glEnd();
                    return readFrame(kSize, kSize);
                },
                kSize, kSize);
            EXPECT_EQ(frames.mygl, frames.osmesa) << culled << " " << face;
        }
    }
}

// A long draw of quads reaches the reference's draw module in segments of 4096 vertices, and each
// segment takes its own path: with a vertex to clip, through the draw module (quads split v1-v3),
// otherwise the direct way (split v0-v2). 1400 smooth quads, one of them crossing the window's
// left edge in the first segment, in the second, or nowhere.
TEST(DrawModuleCulling, LongQuadDrawsChooseThePathPerSegment) {
    constexpr int kWidth = 400, kHeight = 300, kQuads = 1400, kColumns = 40;
    for (const int clippedQuad : {0, 1200, -1}) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                glClearColor(0, 0, 0, 0);
                glClear(GL_COLOR_BUFFER_BIT);
                glMatrixMode(GL_PROJECTION);
                glOrtho(0, kWidth, 0, kHeight, -1, 1);
                glBegin(GL_QUADS);
                for (int q = 0; q < kQuads; ++q) {
                    const float x = static_cast<float>(q % kColumns) * 10.0f + (q == clippedQuad ? -5.0f : 0.3f);
                    const float y = static_cast<float>(q / kColumns) * 8.0f + 0.2f,
                                c = static_cast<float>(q % 7) / 7.0f;
                    glColor3f(1, c, 0), glVertex2f(x, y);
                    glColor3f(0, 1, c), glVertex2f(x + 9, y);
                    glColor3f(c, 0, 1), glVertex2f(x + 9, y + 7);
                    glColor3f(1, 1, c), glVertex2f(x, y + 7);
                }
                glEnd();
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(frames.mygl, frames.osmesa) << "clipped quad " << clippedQuad;
    }
}
