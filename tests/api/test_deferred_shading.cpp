// Deferred shading (TileRasterizer::drawDeferred): textured, depth-tested triangles that cover a
// tile many times over are drawn as depths first, then each pixel is shaded by its winner. The
// frames must be those of the reference, which shades every fragment that passes: ties of equal
// depth (the first fragment keeps the pixel under GL_LESS), depths stored before the run that a
// run's fragment equals, and runs broken by other primitives. Colour and depth are compared with
// a live OSMesa render.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <array>
#include <vector>

#include "backends.h"

using testing_support::clearedPerspectiveView;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 128, kHeight = 96;

// A mipmapped 16 x 16 texture of four colours' stripes (the keys the fast paths defer:
// LINEAR_MIPMAP_LINEAR or NEAREST, REPEAT, MODULATE).
void makeTexture(GLenum minFilter, GLenum magFilter) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0, side = 16; side >= 1; ++level, side /= 2) {
        std::vector<GLubyte> texels;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                const int stripe = (x * 4 / side + y * 2 / side + level) % 4;
                texels.insert(texels.end(), {GLubyte(60 + stripe * 60), GLubyte(240 - stripe * 50), GLubyte(level * 30),
                                             GLubyte(255 - stripe * 20)});
            }
        }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, side, side, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
}

// A quad over most of the window at depth z (eye space), tilted by `tilt`, coloured `color`
// at two corners and a little darker at the others (smooth: the fast paths' textured keys),
// its texture repeated `repeat` times.
void quad(float z, float tilt, const std::array<float, 3>& color, float repeat) {
    const auto corner = [&](float shade, float s, float t, float x, float y, float depth) {
        glColor3f(color[0] * shade, color[1] * shade, color[2] * shade);
        glTexCoord2f(s, t);
        glVertex3f(x, y, depth);
    };
    glBegin(GL_QUADS);
    corner(1.0f, 0, 0, -1.4f, -1.1f, z - tilt);
    corner(0.8f, repeat, 0, 1.4f, -1.1f, z + tilt);
    corner(1.0f, repeat, repeat, 1.4f, 1.1f, z + tilt);
    corner(0.8f, 0, repeat, -1.4f, 1.1f, z - tilt);
    glEnd();
}

const std::array<float, 3> kColors[] = {{1, 1, 1}, {1, 0.5f, 0.5f}, {0.5f, 1, 0.5f}, {0.5f, 0.5f, 1}, {1, 1, 0.3f}};

void expectSameFrames(const std::function<void()>& draw) {
    const auto frames = onBothBackends<Frame>(
        [&] {
            draw();
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_TRUE(frames.mygl.color == frames.osmesa.color) << "colours differ";
    EXPECT_TRUE(frames.mygl.depth == frames.osmesa.depth) << "depths differ";
}

// Twelve crossing quads, far and near interleaved, each drawn twice over itself in another colour:
// the second of two equal depths fails under GL_LESS, so the first colour must stay.
void crossingQuadsTwice() {
    for (int i = 0; i < 12; ++i) {
        const float z = (i % 2 ? 0.4f : -0.4f) + static_cast<float>(i % 5) * 0.07f;
        const float tilt = static_cast<float>(i % 3 - 1) * 0.5f;
        quad(z, tilt, kColors[i % 5], 1.0f + static_cast<float>(i % 4));
        quad(z, tilt, kColors[(i + 2) % 5], 1.0f + static_cast<float>(i % 4));
    }
}

TEST(DeferredShading, EqualDepthsKeepTheFirstFragmentAsTheReference) {
    for (const GLenum filter : {GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST}) {
        SCOPED_TRACE(filter == GL_NEAREST ? "nearest" : "linear mipmap linear");
        expectSameFrames([filter] {
            clearedPerspectiveView(3.0f);
            makeTexture(filter, filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
            crossingQuadsTwice();
        });
    }
}

// Depths stored before the run that the run's first quad equals: the same quad drawn first under
// a colour mask (which is drawn at once, its depths those of the deferred quad). Under GL_LESS the
// deferred quad fails everywhere, though its depth is the pixels' final one.
TEST(DeferredShading, DepthsStoredBeforeTheRunKeepTheirColourAsTheReference) {
    expectSameFrames([] {
        clearedPerspectiveView(3.0f);
        makeTexture(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
        glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
        quad(0.2f, 0.3f, {0.9f, 0.2f, 0.2f}, 2.0f);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        quad(0.2f, 0.3f, {1, 1, 1}, 2.0f);
        for (int i = 0; i < 10; ++i) quad(-0.5f + static_cast<float>(i) * 0.02f, -0.3f, kColors[i % 5], 3.0f);
    });
}

// Runs broken by a blended quad and by lines between the textured quads, and a colour mask that
// turns the deferral off for a few quads in the middle.
TEST(DeferredShading, RunsBrokenByOtherPrimitivesMatchTheReference) {
    expectSameFrames([] {
        clearedPerspectiveView(3.0f);
        makeTexture(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
        crossingQuadsTwice();
        glDisable(GL_TEXTURE_2D);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glColor4f(0.2f, 0.9f, 0.3f, 0.5f);
        glBegin(GL_TRIANGLES);
        glVertex3f(-1.2f, -1.0f, 0.5f), glVertex3f(1.2f, -0.8f, 0.3f), glVertex3f(0.0f, 1.0f, 0.6f);
        glEnd();
        glDisable(GL_BLEND);
        glBegin(GL_LINES);
        glVertex3f(-1.3f, 0.0f, 0.7f), glVertex3f(1.3f, 0.2f, 0.7f);
        glEnd();
        glEnable(GL_TEXTURE_2D);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
        for (int i = 0; i < 3; ++i) quad(0.45f + static_cast<float>(i) * 0.05f, 0.2f, kColors[i], 2.0f);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        for (int i = 0; i < 12; ++i)
            quad(0.3f + static_cast<float>(i % 4) * 0.1f, static_cast<float>(i % 3 - 1) * 0.6f, kColors[i % 5], 2.0f);
    });
}

}  // namespace
