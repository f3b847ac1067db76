// The depth a filled triangle stores equals the reference's, bit for bit: random triangles of
// both windings, inside the window and crossing its sides and the near plane, each drawn alone
// with GL_ALWAYS so that every covered pixel shows its own depth. (Exact on CPUs with FMA, where
// llvmpipe's JIT fuses the plane evaluation as MyGL does; this machine's reference has it.)
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

constexpr int kWidth = 64, kHeight = 48, kTriangles = 200;

struct Triangle {
    float v[3][3];
};

// Draws each triangle into a cleared depth buffer and returns all the depth buffers, one after
// the other; `project` sets the projection and modelview matrices.
std::vector<GLuint> depthOfEach(const std::vector<Triangle>& triangles, void (*project)()) {
    std::vector<GLuint> all;
    std::vector<GLuint> depth(kWidth * kHeight);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    project();
    for (const Triangle& t : triangles) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        for (int k = 0; k < 3; ++k) {
            glColor3f(0.3f * static_cast<float>(k), 0.6f, 0.9f);
            glVertex3fv(t.v[k]);
        }
        glEnd();
        glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
        all.insert(all.end(), depth.begin(), depth.end());
    }
    return all;
}

// Triangles whose differing depth buffers are listed, so that a failure says how many differ.
std::vector<int> differingTriangles(const std::vector<GLuint>& ours, const std::vector<GLuint>& theirs) {
    std::vector<int> differing;
    const std::size_t frame = kWidth * kHeight;
    for (std::size_t i = 0; i * frame < ours.size(); ++i) {
        if (!std::equal(ours.begin() + static_cast<std::ptrdiff_t>(i * frame),
                        ours.begin() + static_cast<std::ptrdiff_t>((i + 1) * frame),
                        theirs.begin() + static_cast<std::ptrdiff_t>(i * frame)))
            differing.push_back(static_cast<int>(i));
    }
    return differing;
}

}  // namespace

// The planes of a triangle clockwise in the window are built from (v1, v0, v2), as llvmpipe sets
// them up; built in the original order, 87 of these 200 depth buffers differ.
TEST(TriangleDepth, BothWindingsInsideTheWindowMatchTheReferenceBitForBit) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> x(0.5f, kWidth - 0.5f), y(0.5f, kHeight - 0.5f), z(-0.95f, 0.95f);
    std::vector<Triangle> triangles(kTriangles);
    for (Triangle& t : triangles)
        for (auto& p : t.v) p[0] = x(random), p[1] = y(random), p[2] = z(random);
    const auto depths = onBothBackends<std::vector<GLuint>>(
        [&] {
            return depthOfEach(triangles, [] {
                glMatrixMode(GL_PROJECTION);
                glOrtho(0, kWidth, 0, kHeight, -1, 1);
                glMatrixMode(GL_MODELVIEW);
            });
        },
        kWidth, kHeight);
    ASSERT_EQ(depths.mygl.size(), depths.osmesa.size());
    EXPECT_EQ(differingTriangles(depths.mygl, depths.osmesa), std::vector<int>{});
}

// Clipping makes new vertices only where edges cross a plane; the triangle's own vertices keep
// the window positions of the vertex stage (fused multiply-add), the new ones get the clipper's
// (separate multiply and add). With the clipper's positions for all vertices, 19 of these 200
// depth buffers differ.
TEST(TriangleDepth, ClippedAtTheSidesAndTheNearPlaneMatchTheReferenceBitForBit) {
    std::mt19937 random(12);
    std::uniform_real_distribution<float> across(-1.3f, 1.3f), depth(-5.0f, -0.3f);
    std::vector<Triangle> triangles(kTriangles);
    for (Triangle& t : triangles) {
        for (auto& p : t.v) {
            p[2] = depth(random);  // the near plane is at -1
            p[0] = across(random) * -p[2] * 0.5f, p[1] = across(random) * -p[2] * 0.4f;
        }
    }
    const auto depths = onBothBackends<std::vector<GLuint>>(
        [&] {
            return depthOfEach(triangles, [] {
                glMatrixMode(GL_PROJECTION);
                glFrustum(-0.5, 0.5, -0.4, 0.4, 1.0, 10.0);
                glMatrixMode(GL_MODELVIEW);
            });
        },
        kWidth, kHeight);
    ASSERT_EQ(depths.mygl.size(), depths.osmesa.size());
    EXPECT_EQ(differingTriangles(depths.mygl, depths.osmesa), std::vector<int>{});
}
