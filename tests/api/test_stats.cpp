// The counters against the reference: OSMesa's GL_SAMPLES_PASSED occlusion query tells, per
// triangle drawn alone with the depth test off, whether it produced fragments. MyGL's counters
// around the same draw must agree exactly, with culling off, back, front and front-and-back.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "backends.h"
#include "samples_passed.h"

namespace {

struct Triangle {
    float v[3][4];
};

// Triangles of both windings, degenerate ones, tiny ones, some outside or across the near plane.
std::vector<Triangle> testTriangles() {
    std::mt19937 random(99);
    std::uniform_real_distribution<float> u(-1.3f, 1.3f), w(-0.3f, 2.0f);
    std::vector<Triangle> triangles;
    for (int i = 0; i < 300; ++i) {
        Triangle t;
        const float scale = i % 5 == 0 ? 0.02f : 1.0f;
        for (auto& v : t.v) {
            const float vw = i % 7 == 0 ? w(random) : 1.0f;
            v[0] = u(random) * scale * vw, v[1] = u(random) * scale * vw, v[2] = u(random) * 0.5f * vw, v[3] = vw;
        }
        if (i % 11 == 0) {  // collinear: zero area
            for (int k = 0; k < 4; ++k) t.v[2][k] = 0.5f * (t.v[0][k] + t.v[1][k]);
        }
        triangles.push_back(t);
    }
    return triangles;
}

void drawTriangle(const Triangle& t) {
    glBegin(GL_TRIANGLES);
    for (const auto& v : t.v) glVertex4fv(v);
    glEnd();
}

void setCulling(GLenum face) {
    if (face == GL_NONE) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(face);
    }
}

}  // namespace

TEST(StatsCrossCheck, TrianglesThatProduceFragmentsMatchOcclusionQueries) {
    const std::vector<Triangle> triangles = testTriangles();
    for (GLenum cull : {GLenum(GL_NONE), GLenum(GL_BACK), GLenum(GL_FRONT), GLenum(GL_FRONT_AND_BACK)}) {
        std::vector<bool> theirs, ours;
        {
            reference::OsmesaContext context(64, 64);
            context.makeCurrent();
            testing_support::SamplesPassedQuery query;
            ASSERT_TRUE(query.available());
            setCulling(cull);
            for (const Triangle& t : triangles) theirs.push_back(query.samplesPassed([&] { drawTriangle(t); }) > 0);
        }
        {
            mygl::Context context(64, 64);
            context.makeCurrent();
            setCulling(cull);
            for (const Triangle& t : triangles) {
                const mygl::Stats before = context.stats();
                drawTriangle(t);
                const mygl::Stats drawn = context.stats() - before;
                ours.push_back(drawn.fragments > 0);
                EXPECT_EQ(drawn.triangles, 1u);
                EXPECT_EQ(
                    drawn.triangles + drawn.clipCreated,
                    drawn.clippedAway + drawn.culledBack + drawn.culledFront + drawn.culledZeroArea + drawn.rasterized);
                if (drawn.rasterized == 0) {
                    EXPECT_EQ(drawn.fragments, 0u);
                }
                if (cull == GL_FRONT_AND_BACK) {
                    EXPECT_EQ(drawn.rasterized, 0u);
                }
            }
        }
        int produced = 0;
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            EXPECT_EQ(ours[i], theirs[i]) << "triangle " << i << " culling " << cull;
            produced += theirs[i];
        }
        if (cull != GL_FRONT_AND_BACK) {
            EXPECT_GT(produced, 20) << "the case must exercise both outcomes";
        }
    }
}

TEST(Stats, CountsResetAtClearAndAddUpForAScene) {
    mygl::Context context(64, 64);
    context.makeCurrent();
    glEnable(GL_CULL_FACE);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -4);
    glRotatef(30, 1, 1, 0);
    glBegin(GL_QUADS);  // a cube: 6 quads, 12 triangles, half of them facing away
    const float c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    for (const auto& f : faces)
        for (int i : f) glVertex3fv(c[i]);
    glEnd();
    const mygl::Stats s = context.stats();
    EXPECT_EQ(s.vertices, 24u);
    EXPECT_EQ(s.primitivesByMode[GL_QUADS], 1u);
    EXPECT_EQ(s.triangles, 12u);
    EXPECT_EQ(s.culledBack, 6u);
    EXPECT_EQ(s.rasterized, 6u);
    EXPECT_GT(s.fragments, 0u);
    EXPECT_EQ(s.fragments, s.fragmentsPassed);
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT_EQ(context.stats().triangles, 0u);
}
