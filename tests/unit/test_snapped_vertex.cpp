// Setup's per-vertex work against the per-triangle code it replaced: the vertex stage's
// snapVertex (snapped once per vertex) gives the same fixed-point position as snap() and the
// same verdict as the scalar reading of the usable test, over random, extreme, huge and NaN
// inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "triangle_setup.h"

using namespace glrenderer;

namespace {

// The test as it read per triangle corner: |x|, |y| below kMaxWindowCoordinate; z, 1 / w and
// the colour finite (NaN fails).
bool usableScalar(const WindowVertex& v) {
    const auto within = [](float c) { return std::fabs(c) < kMaxWindowCoordinate; };
    return within(v.x) && within(v.y) && std::isfinite(v.z) && std::isfinite(v.invW) && std::isfinite(v.color.r) &&
           std::isfinite(v.color.g) && std::isfinite(v.color.b) && std::isfinite(v.color.a);
}

}  // namespace

TEST(SnappedVertex, MatchesSnapAndTheUsableTest) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float special[] = {0.0f,
                             -0.0f,
                             0.5f,
                             -0.5f,
                             639.5f,
                             1e-30f,
                             kMaxWindowCoordinate,
                             -kMaxWindowCoordinate,
                             std::nextafter(kMaxWindowCoordinate, 0.0f),
                             -std::nextafter(kMaxWindowCoordinate, 0.0f),
                             1e30f,
                             -1e30f,
                             inf,
                             -inf,
                             nan};
    std::mt19937 random(5);
    std::uniform_real_distribution<float> window(-2000.0f, 2000.0f), unit(0.0f, 1.0f);
    std::uniform_int_distribution<std::size_t> pick(0, std::size(special) - 1);
    int usableCount = 0;
    for (int i = 0; i < 20000; ++i) {
        WindowVertex v;
        v.x = window(random), v.y = window(random), v.z = unit(random), v.invW = unit(random);
        v.color = {unit(random), unit(random), unit(random), unit(random)};
        float* fields[] = {&v.x, &v.y, &v.z, &v.invW, &v.color.r, &v.color.g, &v.color.b, &v.color.a};
        if (i % 3 == 0) *fields[i / 3 % 8] = special[pick(random)];  // one special field
        if (i % 11 == 1) v.x = special[pick(random)], v.y = special[pick(random)];
        const SnappedVertex snapped = snapVertex(v);
        ASSERT_EQ(snapped.usable, usableScalar(v)) << "vertex " << i << " at " << v.x << ", " << v.y;
        if (!snapped.usable) continue;
        ++usableCount;
        const FixedPoint expected = snap(v);
        ASSERT_EQ(snapped.fixed.x, expected.x) << "vertex " << i;
        ASSERT_EQ(snapped.fixed.y, expected.y) << "vertex " << i;
        ASSERT_EQ(snapped.fixed.x, static_cast<std::int64_t>(std::nearbyint((v.x - 0.5f) * 256.0f)));
    }
    EXPECT_GT(usableCount, 10000);
    EXPECT_LT(usableCount, 20000);
}
