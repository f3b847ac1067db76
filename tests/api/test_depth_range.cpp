// glDepthRange other than [0, 1]: the depth every pixel gets, compared with OSMesa bit for bit.
// The reference keeps the range in double and forms the viewport's depth scale and offset in
// double before rounding them to float; found by differential fuzzing (issue 12).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <random>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kSize = 16;

// A triangle sloping through the whole depth range, drawn with the depth test on.
Frame drawWithDepthRange(double nearVal, double farVal) {
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthRange(nearVal, farVal);
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.9f, -0.9f, -0.97f);
    glVertex3f(0.95f, -0.4f, 0.31f);
    glVertex3f(-0.1f, 0.9f, 0.93f);
    glEnd();
    return readFrame(kSize, kSize);
}

}  // namespace

TEST(DepthRange, DepthOfEveryPixelMatchesTheReference) {
    std::mt19937 random(12);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int differing = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const double nearVal = unit(random), farVal = unit(random);
        const auto frames = onBothBackends<Frame>([&] { return drawWithDepthRange(nearVal, farVal); }, kSize, kSize);
        if (frames.mygl != frames.osmesa) ++differing;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << "glDepthRange(" << nearVal << ", " << farVal << ")";
        if (differing > 3) break;
    }
}

TEST(DepthRange, QueriesAnswerAsTheReference) {
    const auto values = onBothBackends<std::vector<double>>([] {
        glDepthRange(0.1, 0.3);
        std::vector<double> out(6);
        glGetDoublev(GL_DEPTH_RANGE, out.data());
        GLfloat floats[2];
        glGetFloatv(GL_DEPTH_RANGE, floats);
        GLint ints[2];
        glGetIntegerv(GL_DEPTH_RANGE, ints);
        out[2] = floats[0];
        out[3] = floats[1];
        out[4] = ints[0];
        out[5] = ints[1];
        return out;
    });
    EXPECT_EQ(values.mygl, values.osmesa);
}
