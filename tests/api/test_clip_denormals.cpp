// Clipping where a crossing's parameter is denormal: a vertex near FLT_MAX or at w = 0. The
// reference draws with denormals flushed to zero (its draw module sets MXCSR FTZ and DAZ for each
// draw), so such a crossing lands on the vertex it is interpolated from. Compared with OSMesa bit
// for bit; found by differential fuzzing (issue 12).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

Frame drawOnCleared(int width, int height, void (*draw)()) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw();
    return readFrame(width, height);
}

}  // namespace

TEST(ClipDenormals, RectangleReachingFltMaxIsClippedAsTheReferenceDoes) {
    // The edge from y = 0 to y = 3.4e38 crosses y = w at t = 1 / 3.4e38, a denormal: flushed,
    // the crossing is y = 0 and nothing is left to draw.
    const auto frames = onBothBackends<Frame>(
        [] {
            return drawOnCleared(6, 2, [] {
                const GLfloat a[2] = {0.0f, 3.4e38f}, b[2] = {1.0f, 0.0f};
                glRectfv(a, b);
            });
        },
        6, 2);
    EXPECT_EQ(frames.mygl, frames.osmesa);
}
