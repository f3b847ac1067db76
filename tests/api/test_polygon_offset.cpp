// Polygon offset: generated triangles and quads across factors and units, filled and unfilled,
// compared with OSMesa running the very same calls (depth to the last bit, and the colours that
// the offset decides through the depth test); glPolygonOffset's state likewise.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::differingPixels;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 80, kHeight = 64;

struct Offset {
    float factor, units;
};

// Random triangles with random depth slopes in a perspective view, drawn once plainly and then
// again offset in another colour with GL_LEQUAL (the offset decides which colour shows), front
// faces in `mode` (GL_FILL, GL_LINE or GL_POINT) with that mode's offset enable, back faces in
// `backMode` (the same unless given).
Frame offsetFrame(Offset offset, GLenum mode, unsigned seed, GLenum backMode = 0) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -0.8, 0.8, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> xy(-2.5f, 2.5f), z(-9.0f, -1.5f);
    std::vector<float> vertices(3 * 3 * 12);
    for (float& v : vertices) v = 0.0f;
    for (std::size_t i = 0; i < vertices.size(); i += 3) {
        vertices[i] = xy(random), vertices[i + 1] = xy(random), vertices[i + 2] = z(random);
    }
    const auto draw = [&] {
        glBegin(GL_TRIANGLES);
        for (std::size_t i = 0; i < vertices.size(); i += 3) glVertex3fv(&vertices[i]);
        glEnd();
    };
    glColor3f(0.8f, 0.2f, 0.2f);
    draw();
    const GLenum enable = mode == GL_FILL   ? GL_POLYGON_OFFSET_FILL
                          : mode == GL_LINE ? GL_POLYGON_OFFSET_LINE
                                            : GL_POLYGON_OFFSET_POINT;
    glEnable(enable);
    glPolygonOffset(offset.factor, offset.units);
    glPolygonMode(GL_FRONT, mode);
    glPolygonMode(GL_BACK, backMode ? backMode : mode);
    glColor3f(0.2f, 0.9f, 0.3f);
    draw();
    return readFrame(kWidth, kHeight);
}

}  // namespace

TEST(PolygonOffset, GeneratedFactorsAndUnitsMatchTheReference) {
    const Offset offsets[] = {{0.0f, 1.0f}, {0.0f, -1.0f}, {0.0f, 50.0f},  {1.0f, 0.0f},   {-1.0f, 0.0f},
                              {1.0f, 1.0f}, {2.5f, -3.0f}, {-1.0f, -1.0f}, {0.5f, 1000.0f}};
    for (GLenum mode : {GL_FILL, GL_LINE, GL_POINT}) {
        for (const Offset& o : offsets) {
            for (unsigned seed : {1u, 2u, 3u}) {
                const auto frames = onBothBackends<Frame>([&] { return offsetFrame(o, mode, seed); }, kWidth, kHeight);
                EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0)
                    << "mode " << mode << " factor " << o.factor << " units " << o.units << " seed " << seed;
            }
        }
    }
}

TEST(PolygonOffset, StateQueriesMatchTheReference) {
    const auto answers = onBothBackends<std::vector<float>>([] {
        std::vector<float> a;
        const auto read = [&] {
            GLfloat v = 0;
            for (GLenum name : {GL_POLYGON_OFFSET_FACTOR, GL_POLYGON_OFFSET_UNITS}) {
                glGetFloatv(name, &v);
                a.push_back(v);
            }
            for (GLenum cap : {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT}) {
                a.push_back(glIsEnabled(cap));
            }
            a.push_back(static_cast<float>(glGetError()));
        };
        read();
        glPolygonOffset(1.5f, -2.0f);
        glEnable(GL_POLYGON_OFFSET_LINE);
        read();
        glPushAttrib(GL_POLYGON_BIT);
        glPolygonOffset(3.0f, 4.0f);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_POLYGON_OFFSET_LINE);
        read();
        glPopAttrib();
        read();
        glBegin(GL_TRIANGLES);
        glPolygonOffset(1.0f, 1.0f);
        glEnd();
        read();
        return a;
    });
    EXPECT_EQ(answers.mygl, answers.osmesa);
}

// Faces of one draw in different polygon modes go through the reference's draw module, whose
// offset stage offsets the filled ones too, per vertex (not as setup does, per fragment).
TEST(PolygonOffset, FilledFacesBesideUnfilledOnesTakeTheDrawModulesOffset) {
    const Offset offsets[] = {{0.0f, 1.0f}, {1.0f, 0.0f}, {2.5f, -3.0f}, {0.5f, 1000.0f}};
    for (GLenum backMode : {GL_LINE, GL_POINT}) {
        for (const Offset& o : offsets) {
            for (unsigned seed : {1u, 2u, 3u}) {
                const auto frames =
                    onBothBackends<Frame>([&] { return offsetFrame(o, GL_FILL, seed, backMode); }, kWidth, kHeight);
                EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0)
                    << "back mode " << backMode << " factor " << o.factor << " units " << o.units << " seed " << seed;
            }
        }
    }
}
