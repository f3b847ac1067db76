// Whether a draw's vertices carry colors of their own (glColor inside glBegin/glEnd) or share the
// current color set before glBegin changes what the reference draws: a shared color is a
// constant of the draw (smooth shading does not interpolate it), flat quads are then split on
// the v0-v2 diagonal, and the first glColor inside glBegin/glEnd ends the draw before it. Each
// case is compared with OSMesa bit for bit, colors and depth.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <string>
#include <vector>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;

namespace {

constexpr int kWidth = 96, kHeight = 72;

// A perspective view where interpolating a color blurs it and where the split of a quad shows
// in the last bits of its depth.
void perspective(GLenum shadeModel) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glShadeModel(shadeModel);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(55.0f, 1.0f, 0.3f, 0.0f);
    glColor3f(0.8f, 0.1f, 0.3f);
}

void quad(float x0, float x1, bool colorPerVertex) {
    const float xs[4] = {x0, x1, x1 - 0.05f, x0 + 0.1f}, ys[4] = {-1.2f, -1.1f, 1.3f, 1.15f};
    for (int i = 0; i < 4; ++i) {
        if (colorPerVertex) glColor3f(0.8f, 0.1f, 0.3f);
        glVertex3f(xs[i], ys[i], 0.15f * static_cast<float>(i));
    }
}

struct Variant {
    const char* name;
    GLenum shadeModel;
    bool firstColored, secondColored, oneBlock;
};

void draw(const Variant& v) {
    perspective(v.shadeModel);
    glBegin(GL_QUADS);
    quad(-1.4f, -0.2f, v.firstColored);
    if (!v.oneBlock) {
        glEnd();
        glBegin(GL_QUADS);
    }
    quad(0.1f, 1.3f, v.secondColored);
    glEnd();
}

}  // namespace

TEST(CurrentColor, DrawsAsTheReferenceWhetherColorsComePerVertexOrNot) {
    const Variant variants[] = {
        {"smooth, one color for all", GL_SMOOTH, false, false, false},
        {"smooth, a color per vertex", GL_SMOOTH, true, true, false},
        {"flat, one color for all", GL_FLAT, false, false, false},
        {"flat, a color per vertex", GL_FLAT, true, true, false},
        {"flat, colors from the second block on", GL_FLAT, false, true, false},
        {"flat, colors from the second quad of one block on", GL_FLAT, false, true, true},
        {"flat, colors in the first block only", GL_FLAT, true, false, false},
    };
    for (const Variant& variant : variants) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                draw(variant);
                return testing_support::readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(frames.mygl.color, frames.osmesa.color) << variant.name;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << variant.name;
    }
}
