// Points, lines and smooth primitives are queued in the tiles with the triangles (issue 14):
// drawn with blending and without the depth test, where the order of primitives decides every
// overlapped pixel, interleaved with triangles across many tile borders, each frame compared
// with OSMesa running the very same calls (colour and depth of every pixel).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <functional>
#include <random>

#include "backends.h"
#include "color_difference.h"

using testing_support::differingPixels;
using testing_support::Frame;

namespace {

// Big enough for several rows and columns of tiles (64 pixels square at this size).
constexpr int kWidth = 301, kHeight = 203;

testing_support::BothResults<Frame> render(const std::function<void()>& draw) {
    return testing_support::onBothBackends<Frame>(
        [&] {
            const GLfloat clear[4] = {0.1f, 0.2f, 0.3f, 0.6f};
            testing_support::clearedOrthoView(kWidth, kHeight, clear, 1.0, 0);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            draw();
            return testing_support::readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
}

// Random primitives of every kind in a random order, each crossing tile borders often.
void interleaved(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(-10.0f, kWidth + 10.0f), y(-10.0f, kHeight + 10.0f), unit(0.0f, 1.0f);
    const GLenum modes[] = {GL_TRIANGLES, GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_QUADS};
    for (int draw = 0; draw < 40; ++draw) {
        const GLenum mode = modes[rng() % 5];
        glLineWidth(1.0f + static_cast<float>(rng() % 6));
        glPointSize(1.0f + static_cast<float>(rng() % 9));
        glPolygonMode(GL_FRONT_AND_BACK, rng() % 3 == 0 ? GL_LINE : GL_FILL);
        glBegin(mode);
        for (int v = 0; v < 8; ++v) {
            glColor4f(unit(rng), unit(rng), unit(rng), 0.4f + 0.5f * unit(rng));
            glVertex3f(x(rng), y(rng), unit(rng) * 1.8f - 0.9f);
        }
        glEnd();
    }
}

TEST(TiledPointsAndLines, InterleavedWithTrianglesAsOsmesa) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const auto frames = render([&] { interleaved(seed); });
        EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0) << "seed " << seed;
    }
}

TEST(TiledPointsAndLines, SmoothStippledScissoredAndDepthTestedAsOsmesa) {
    const std::function<void()> setups[] = {
        [] { glEnable(GL_LINE_SMOOTH), glEnable(GL_POINT_SMOOTH); },
        [] { glEnable(GL_LINE_STIPPLE), glLineStipple(2, 0x33F1); },
        [] { glEnable(GL_SCISSOR_TEST), glScissor(37, 21, 150, 120); },
        [] { glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LEQUAL); },
    };
    for (std::size_t i = 0; i < std::size(setups); ++i) {
        const auto frames = render([&] {
            setups[i]();
            interleaved(static_cast<unsigned>(10 + i));
        });
        EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0) << "setup " << i;
    }
}

// Everything the frame draws, drawn early in parts by the batch thread or at the end, lands in
// the same order: many small draws, then a clear of part of the frame, then more.
TEST(TiledPointsAndLines, ManyDrawsAroundAScissoredClearAsOsmesa) {
    const auto frames = render([] {
        for (int round = 0; round < 30; ++round) interleaved(100 + static_cast<unsigned>(round));
        glEnable(GL_SCISSOR_TEST);
        glScissor(50, 40, 100, 90);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        interleaved(200);
    });
    EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0);
}

}  // namespace
