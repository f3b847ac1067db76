// Dense meshes of tiny triangles, whose fragments the fast paths pack into shared blocks of lanes
// (packed_triangles.h), against a live OSMesa render: a grid of cells about two pixels across,
// folded over itself (a run's triangles cover the same pixels again), drawn twice (depth ties
// under GL_LESS and GL_LEQUAL), with per-vertex and flat colours, blending, fog whose colour
// changes between draws, polygon offset and a mipmapped texture; and the fragments that pass
// against OSMesa's GL_SAMPLES_PASSED occlusion query.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <cmath>
#include <functional>
#include <vector>

#include "backends.h"
#include "samples_passed.h"

using testing_support::clearedPerspectiveView;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 128, kHeight = 96;
constexpr int kColumns = 64, kRows = 48;

// The grid's vertex (i, j): x folded by a sine steep enough to turn back on itself, z a gentle
// wave, its colour from its place and `shade`, alpha 0.6, texture coordinates repeating.
void gridVertex(int i, int j, float shade) {
    const float u = static_cast<float>(i) / kColumns, v = static_cast<float>(j) / kRows;
    const float x = -2.3f + 4.6f * u + 0.15f * std::sin(40.0f * u);
    const float y = -1.7f + 3.4f * v, z = 0.3f * std::sin(4.0f * u) * std::cos(3.0f * v);
    glColor4f(shade * u, shade * (1.0f - v), 0.5f + 0.5f * shade * u * v, 0.6f);
    glTexCoord2f(4.0f * u, 3.0f * v);
    glVertex3f(x, y, z);
}

void foldedMesh(float shade) {
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < kRows; ++j) {
        for (int i = 0; i < kColumns; ++i) {
            gridVertex(i, j, shade), gridVertex(i + 1, j, shade), gridVertex(i + 1, j + 1, shade);
            gridVertex(i, j, shade), gridVertex(i + 1, j + 1, shade), gridVertex(i, j + 1, shade);
        }
    }
    glEnd();
}

// A mipmapped 16 x 16 texture of stripes, LINEAR_MIPMAP_LINEAR, REPEAT, MODULATE.
void mipmappedTexture() {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0, side = 16; side >= 1; ++level, side /= 2) {
        std::vector<GLubyte> texels;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                const int stripe = (x * 4 / side + y * 2 / side + level) % 4;
                texels.insert(texels.end(),
                              {GLubyte(60 + stripe * 60), GLubyte(240 - stripe * 50), GLubyte(level * 30)});
            }
        }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
}

void linearFog(float red) {
    const GLfloat color[4] = {red, 0.5f, 0.6f, 1.0f};
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 4.5f);
    glFogfv(GL_FOG_COLOR, color);
}

void expectSameFrames(const std::function<void()>& draw) {
    const auto frames = onBothBackends<Frame>(
        [&] {
            clearedPerspectiveView(3.0f);
            draw();
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_TRUE(frames.mygl.color == frames.osmesa.color) << "colours differ";
    EXPECT_TRUE(frames.mygl.depth == frames.osmesa.depth) << "depths differ";
}

}  // namespace

TEST(PackedTriangles, FoldedMeshesDrawnTwiceMatchTheReference) {
    for (const GLenum func : {GL_LESS, GL_LEQUAL}) {
        for (const GLenum shading : {GL_SMOOTH, GL_FLAT}) {
            SCOPED_TRACE(testing::Message() << "depth func " << func << " shading " << shading);
            expectSameFrames([func, shading] {
                glDepthFunc(func);
                glShadeModel(shading);
                foldedMesh(1.0f);
                foldedMesh(0.5f);
            });
        }
    }
}

TEST(PackedTriangles, BlendedFoggedAndOffsetMeshesMatchTheReference) {
    {
        SCOPED_TRACE("blending without depth writes");
        expectSameFrames([] {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
            foldedMesh(1.0f);
            foldedMesh(0.5f);
        });
    }
    {
        SCOPED_TRACE("fog, its colour changed between the draws");
        expectSameFrames([] {
            linearFog(0.2f);
            foldedMesh(1.0f);
            linearFog(0.9f);
            glDepthFunc(GL_LEQUAL);
            foldedMesh(0.5f);
        });
    }
    {
        SCOPED_TRACE("polygon offset");
        expectSameFrames([] {
            foldedMesh(1.0f);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(-1.0f, -2.0f);
            foldedMesh(0.5f);
        });
    }
}

// bench-fog-textured-terrain's key (a level of detail per 2 x 2 quad, from each triangle's own
// planes), and the same without fog.
TEST(PackedTriangles, TexturedMeshesWithALevelOfDetailMatchTheReference) {
    for (const bool fog : {true, false}) {
        SCOPED_TRACE(fog ? "fog" : "no fog");
        expectSameFrames([fog] {
            mipmappedTexture();
            if (fog) linearFog(0.4f);
            foldedMesh(1.0f);
            foldedMesh(0.5f);
        });
    }
}

// The fragments that pass the depth test in each of the two draws (the second's ties fail under
// GL_LESS): MyGL's count against OSMesa's samples passed.
TEST(PackedTriangles, FragmentsPassedMatchOcclusionQueries) {
    std::vector<GLuint> theirs;
    {
        reference::OsmesaContext context(kWidth, kHeight);
        context.makeCurrent();
        testing_support::SamplesPassedQuery query;
        ASSERT_TRUE(query.available());
        clearedPerspectiveView(3.0f);
        for (const float shade : {1.0f, 0.5f}) theirs.push_back(query.samplesPassed([&] { foldedMesh(shade); }));
    }
    std::vector<GLuint> ours;
    {
        mygl::Context context(kWidth, kHeight);
        context.makeCurrent();
        clearedPerspectiveView(3.0f);
        for (const float shade : {1.0f, 0.5f}) {
            const mygl::Stats before = context.stats();
            foldedMesh(shade);
            glFinish();
            ours.push_back(static_cast<GLuint>((context.stats() - before).fragmentsPassed));
        }
    }
    EXPECT_EQ(ours, theirs);
    EXPECT_GT(theirs[0], static_cast<GLuint>(kWidth * kHeight * 3 / 4));  // the mesh covers most of the window
}
