// The per-fragment operations (issue 16): scissor, alpha test, stencil, blending, logic op,
// colour mask and masked clears. Generated cases draw triangles (smooth and flat), lines,
// points and a bitmap on MyGL and on OSMesa running the very same calls, and compare colour,
// depth and stencil to the last bit; the state's queries, attribute groups and errors likewise.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::difference;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 48, kHeight = 40;

struct StencilFrame {
    Frame frame;
    std::vector<GLubyte> stencil;
    bool operator==(const StencilFrame&) const = default;
};

StencilFrame readStencilFrame() {
    StencilFrame f{readFrame(kWidth, kHeight), std::vector<GLubyte>(kWidth * kHeight)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, f.stencil.data());
    return f;
}

// An orthographic view of [0, 48] x [0, 40] with depth in [-1, 1], cleared.
void clearedView() { testing_support::clearedOrthoView(kWidth, kHeight, {0.2f, 0.4f, 0.6f, 0.5f}, 1.0, 0); }

// Every kind of primitive, with colours and alphas spread over [0, 1] and depths over the
// range: two smooth triangles, a flat quad, wide lines, points and a bitmap.
void drawScene(float shift) {
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.1f, 0.0f, 0.0f), glVertex3f(2 + shift, 2, -0.8f);
    glColor4f(0.1f, 1.0f, 0.3f, 1.0f), glVertex3f(40, 6 + shift, 0.5f);
    glColor4f(0.4f, 0.2f, 1.0f, 0.5f), glVertex3f(10, 37, 0.1f);
    glColor4f(0.9f, 0.9f, 0.1f, 0.8f), glVertex3f(46, 38, 0.9f);
    glColor4f(0.0f, 0.5f, 0.5f, 0.2f), glVertex3f(8 + shift, 20, -0.9f);
    glColor4f(0.7f, 0.0f, 0.7f, 0.6f), glVertex3f(30, 1, 0.0f);
    glEnd();
    glShadeModel(GL_FLAT);
    glColor4f(0.3f, 0.8f, 0.6f, 0.7f);
    glRectf(20 + shift, 12, 34, 30);
    glShadeModel(GL_SMOOTH);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    glColor4f(1.0f, 1.0f, 1.0f, 0.3f), glVertex3f(1, 39, -0.5f);
    glColor4f(0.0f, 0.0f, 0.0f, 0.9f), glVertex3f(47, 1 + shift, 0.5f);
    glEnd();
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; ++i) {
        const float f = static_cast<float>(i);
        glColor4f(0.15f * f, 0.9f - 0.1f * f, 0.5f, 0.18f * f), glVertex3f(4.0f + 7.0f * f, 33, 0.3f);
    }
    glEnd();
    static const GLubyte bitmap[8] = {0xFF, 0x81, 0xBD, 0xA5, 0xA5, 0xBD, 0x81, 0xFF};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor4f(0.95f, 0.3f, 0.45f, 0.55f);
    glRasterPos3f(38, 24, 0.2f);
    glBitmap(8, 8, 0, 0, 0, 0, bitmap);
}

// Where two frames first differ, for a failure's message.
std::string firstDifference(const StencilFrame& a, const StencilFrame& b) {
    for (std::size_t p = 0; p < a.stencil.size(); ++p) {
        const bool same = a.stencil[p] == b.stencil[p] && a.frame.depth[p] == b.frame.depth[p] &&
                          std::equal(&a.frame.color[4 * p], &a.frame.color[4 * p + 4], &b.frame.color[4 * p]);
        if (same) continue;
        std::ostringstream out;
        out << "first difference at (" << p % kWidth << ", " << p / kWidth << "): colour";
        for (const StencilFrame* f : {&a, &b}) {
            for (int c = 0; c < 4; ++c) out << ' ' << int(f->frame.color[4 * p + c]);
            out << " depth " << f->frame.depth[p] << " stencil " << int(f->stencil[p])
                << (f == &a ? " (MyGL) vs" : " (OSMesa)\n");
        }
        return out.str();
    }
    return {};
}

void expectIdentical(const std::function<StencilFrame()>& calls, const std::string& label) {
    const auto frames = onBothBackends<StencilFrame>(calls, kWidth, kHeight);
    const auto d = difference(frames.mygl.frame, frames.osmesa.frame);
    EXPECT_EQ(d.pixels, 0) << label << ": largest channel difference " << d.maxChannel;
    EXPECT_TRUE(frames.mygl.frame.depth == frames.osmesa.frame.depth) << label << ": depth";
    EXPECT_TRUE(frames.mygl.stencil == frames.osmesa.stencil) << label << ": stencil";
    if (!(frames.mygl == frames.osmesa)) std::cerr << firstDifference(frames.mygl, frames.osmesa);
}

constexpr GLenum kCompareFuncs[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
constexpr GLenum kStencilOps[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT};
constexpr GLenum kBlendFactors[] = {GL_ZERO,
                                    GL_ONE,
                                    GL_SRC_COLOR,
                                    GL_ONE_MINUS_SRC_COLOR,
                                    GL_DST_COLOR,
                                    GL_ONE_MINUS_DST_COLOR,
                                    GL_SRC_ALPHA,
                                    GL_ONE_MINUS_SRC_ALPHA,
                                    GL_DST_ALPHA,
                                    GL_ONE_MINUS_DST_ALPHA,
                                    GL_SRC_ALPHA_SATURATE};

}  // namespace

TEST(FragmentOps, ScissorBoxesCutEveryPrimitiveAndClear) {
    const std::array<GLint, 4> boxes[] = {{5, 7, 20, 15},          {-10, -10, 30, 25},
                                          {30, 20, 1000, 1000},    {0, 0, 0, 0},
                                          {47, 39, 1, 1},          {-2147483647, 3, 2147483647, 5},
                                          {12, -5, 9, 2147483647}, {60, 50, 10, 10}};
    for (const auto& b : boxes) {
        expectIdentical(
            [&] {
                clearedView();
                glEnable(GL_DEPTH_TEST);
                glEnable(GL_SCISSOR_TEST);
                glScissor(b[0], b[1], b[2], b[3]);
                glClearColor(0.9f, 0.1f, 0.1f, 1.0f);
                glClearStencil(5);
                glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
                drawScene(0.0f);
                return readStencilFrame();
            },
            "scissor " + std::to_string(b[0]) + " " + std::to_string(b[1]) + " " + std::to_string(b[2]) + " " +
                std::to_string(b[3]));
    }
}

TEST(FragmentOps, AlphaFunctionsAndReferencesMatch) {
    for (GLenum func : kCompareFuncs) {
        for (float ref : {-1.0f, 0.0f, 0.25f, 0.5f, 0.501f, 0.7f, 1.0f, 2.0f}) {
            expectIdentical(
                [&] {
                    clearedView();
                    glEnable(GL_ALPHA_TEST);
                    glAlphaFunc(func, ref);
                    drawScene(0.0f);
                    return readStencilFrame();
                },
                "alpha func " + std::to_string(func) + " ref " + std::to_string(ref));
        }
    }
}

// A first pass writes stencil values 1..3 in overlapping shapes; the second tests them with each
// function and each operation in each of the three places, under value and write masks.
TEST(FragmentOps, StencilFunctionsOperationsAndMasksMatch) {
    int index = 0;
    for (GLenum func : kCompareFuncs) {
        for (GLenum op : kStencilOps) {
            for (int place = 0; place < 3; ++place, ++index) {
                const GLuint valueMask = index % 3 == 0 ? 0xFF : index % 3 == 1 ? 0x03 : 0xFE;
                const GLuint writeMask = index % 4 == 0 ? 0xFF : index % 4 == 1 ? 0x0F : index % 4 == 2 ? 0xF1 : 0x00;
                const GLint ref = index % 5 == 0   ? 2
                                  : index % 5 == 1 ? 1
                                  : index % 5 == 2 ? 300
                                  : index % 5 == 3 ? -4
                                                   : 3;
                expectIdentical(
                    [&] {
                        clearedView();
                        glEnable(GL_DEPTH_TEST);
                        glEnable(GL_STENCIL_TEST);
                        glClearStencil(0xF0);
                        glClear(GL_STENCIL_BUFFER_BIT);
                        glStencilFunc(GL_ALWAYS, 1, 0xFF);
                        glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
                        drawScene(0.0f);
                        glStencilFunc(func, ref, valueMask);
                        glStencilMask(writeMask);
                        const GLenum ops[3] = {place == 0 ? op : GL_KEEP, place == 1 ? op : GL_KEEP,
                                               place == 2 ? op : GL_KEEP};
                        glStencilOp(ops[0], ops[1], ops[2]);
                        drawScene(3.0f);
                        glDisable(GL_DEPTH_TEST);
                        drawScene(-2.0f);
                        return readStencilFrame();
                    },
                    "stencil func " + std::to_string(func) + " op " + std::to_string(op) + " place " +
                        std::to_string(place));
            }
        }
    }
}

TEST(FragmentOps, StencilSaturatesAndInverts) {
    for (GLenum op : {GL_INCR, GL_DECR, GL_INVERT}) {
        expectIdentical(
            [&] {
                clearedView();
                glEnable(GL_STENCIL_TEST);
                glClearStencil(op == GL_DECR ? 1 : 254);
                glClear(GL_STENCIL_BUFFER_BIT);
                glStencilOp(op, op, op);
                for (int i = 0; i < 3; ++i) drawScene(float(i));
                return readStencilFrame();
            },
            "stencil op " + std::to_string(op));
    }
}

TEST(FragmentOps, EveryBlendFactorPairMatches) {
    for (GLenum src : kBlendFactors) {
        for (GLenum dst : kBlendFactors) {
            expectIdentical(
                [&] {
                    clearedView();
                    glEnable(GL_DEPTH_TEST);
                    glDepthFunc(GL_LEQUAL);
                    drawScene(2.0f);  // a background of varied colours and alphas
                    glEnable(GL_BLEND);
                    glBlendFunc(src, dst);
                    drawScene(0.0f);
                    return readStencilFrame();
                },
                "blend " + std::to_string(src) + " " + std::to_string(dst));
        }
    }
}

TEST(FragmentOps, EveryLogicOpMatchesAndOverridesBlending) {
    for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
        expectIdentical(
            [&] {
                clearedView();
                drawScene(2.0f);
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE);
                glEnable(GL_COLOR_LOGIC_OP);
                glLogicOp(op);
                drawScene(0.0f);
                return readStencilFrame();
            },
            "logic op " + std::to_string(op));
    }
}

TEST(FragmentOps, ColorMasksApplyToDrawsAndClears) {
    for (int mask = 0; mask < 16; ++mask) {
        expectIdentical(
            [&] {
                clearedView();
                glEnable(GL_DEPTH_TEST);
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                glColorMask(mask & 1, mask & 2, mask & 4, mask & 8);
                drawScene(0.0f);
                glDepthMask(mask & 1);
                glEnable(GL_SCISSOR_TEST);
                glScissor(10, 10, 20, 12);
                glClearColor(0.0f, 1.0f, 0.5f, 0.25f);
                glClearDepth(0.25);
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                return readStencilFrame();
            },
            "colour mask " + std::to_string(mask));
    }
}

TEST(FragmentOps, AllOperationsTogetherMatch) {
    expectIdentical(
        [] {
            clearedView();
            glEnable(GL_DEPTH_TEST);
            glEnable(GL_SCISSOR_TEST);
            glScissor(3, 2, 40, 35);
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(GL_GREATER, 0.1f);
            glEnable(GL_STENCIL_TEST);
            glStencilFunc(GL_NOTEQUAL, 2, 0xFF);
            glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE);
            for (int i = 0; i < 4; ++i) drawScene(1.5f * static_cast<float>(i));
            return readStencilFrame();
        },
        "all operations");
}

TEST(FragmentOps, StateQueriesAttribGroupsAndErrorsMatch) {
    const auto answers = onBothBackends<std::vector<double>>([] {
        std::vector<double> a;
        const auto read = [&] {
            GLint i[4] = {};
            GLfloat f = 0;
            GLboolean b[4] = {};
            for (GLenum name : {GL_SCISSOR_BOX}) {
                glGetIntegerv(name, i);
                a.insert(a.end(), i, i + 4);
            }
            for (GLenum name :
                 {GL_ALPHA_TEST_FUNC, GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_WRITEMASK,
                  GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_CLEAR_VALUE,
                  GL_STENCIL_BITS, GL_BLEND_SRC, GL_BLEND_DST, GL_LOGIC_OP_MODE, GL_SCISSOR_TEST, GL_BLEND}) {
                glGetIntegerv(name, i);
                a.push_back(i[0]);
            }
            glGetFloatv(GL_ALPHA_TEST_REF, &f);
            a.push_back(f);
            glGetBooleanv(GL_COLOR_WRITEMASK, b);
            a.insert(a.end(), b, b + 4);
            for (GLenum cap : {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND, GL_COLOR_LOGIC_OP,
                               GL_INDEX_LOGIC_OP, GL_DITHER}) {
                a.push_back(glIsEnabled(cap));
            }
            a.push_back(glGetError());
        };
        read();
        glScissor(1, 2, 3, 4);
        glAlphaFunc(GL_GEQUAL, 1.5f);
        glStencilFunc(GL_LESS, 300, 0x1234);
        glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
        glStencilMask(0xF0F0);
        glClearStencil(77);
        glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_DST_ALPHA);
        glLogicOp(GL_XOR);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        for (GLenum cap :
             {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP}) {
            glEnable(cap);
        }
        glDisable(GL_DITHER);
        read();
        glPushAttrib(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_SCISSOR_BIT);
        glScissor(5, 6, 7, 8);
        glAlphaFunc(GL_NEVER, 0.25f);
        glStencilFunc(GL_EQUAL, -3, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glStencilMask(1);
        glClearStencil(3);
        glBlendFunc(GL_ONE, GL_ONE);
        glLogicOp(GL_NAND);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
        for (GLenum cap : {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND, GL_COLOR_LOGIC_OP})
            glDisable(cap);
        read();
        glPopAttrib();
        read();
        glPushAttrib(GL_ENABLE_BIT);
        for (GLenum cap : {GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND, GL_COLOR_LOGIC_OP})
            glDisable(cap);
        read();
        glPopAttrib();
        read();
        // Errors: bad enums, negative scissor sizes, calls inside glBegin/glEnd.
        glScissor(0, 0, -1, 5);
        a.push_back(glGetError());
        glScissor(0, 0, 5, -1);
        a.push_back(glGetError());
        glAlphaFunc(GL_ZERO, 0.5f);
        a.push_back(glGetError());
        glStencilFunc(GL_KEEP, 0, 0);
        a.push_back(glGetError());
        glStencilOp(GL_KEEP, GL_ONE, GL_KEEP);
        a.push_back(glGetError());
        glBlendFunc(GL_LESS, GL_ONE);
        a.push_back(glGetError());
        glBlendFunc(GL_ONE, GL_NEVER);
        a.push_back(glGetError());
        glLogicOp(GL_ZERO);
        a.push_back(glGetError());
        glBegin(GL_POINTS);
        glScissor(0, 0, 1, 1);
        glEnd();
        a.push_back(glGetError());
        glBegin(GL_POINTS);
        glBlendFunc(GL_ONE, GL_ONE);
        glEnd();
        a.push_back(glGetError());
        glBegin(GL_POINTS);
        glStencilMask(0);
        glEnd();
        a.push_back(glGetError());
        read();
        return a;
    });
    ASSERT_EQ(answers.mygl.size(), answers.osmesa.size());
    for (std::size_t i = 0; i < answers.mygl.size(); ++i) {
        EXPECT_EQ(answers.mygl[i], answers.osmesa[i]) << "answer " << i;
    }
}

TEST(FragmentOps, DisplayListsCompileTheOperations) {
    expectIdentical(
        [] {
            clearedView();
            const GLuint list = glGenLists(1);
            glNewList(list, GL_COMPILE);
            glEnable(GL_SCISSOR_TEST);
            glScissor(4, 4, 36, 30);
            glEnable(GL_STENCIL_TEST);
            glStencilFunc(GL_ALWAYS, 7, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            glStencilMask(0x3F);
            glClearStencil(1);
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_SRC_COLOR);
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(GL_LESS, 0.6f);
            glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
            glEndList();
            glCallList(list);
            drawScene(0.0f);
            glDisable(GL_SCISSOR_TEST);
            glClear(GL_STENCIL_BUFFER_BIT);
            glCallList(list);
            glEnable(GL_COLOR_LOGIC_OP);
            glLogicOp(GL_OR_REVERSE);
            drawScene(1.0f);
            return readStencilFrame();
        },
        "display list");
}

// Blending of colours interpolated with perspective, in layers of quads.
TEST(FragmentOps, PerspectiveBlendedLayersMatch) {
    for (int n : {1, 2, 5, 20, 200}) {
        expectIdentical(
            [n] {
                clearedView();
                glMatrixMode(GL_PROJECTION);
                glLoadIdentity();
                glFrustum(-1, 1, -0.8, 0.8, 1, 20);
                glMatrixMode(GL_MODELVIEW);
                glLoadIdentity();
                glTranslatef(0, 0, -3);
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                glBegin(GL_QUADS);
                for (int i = 0; i < n; ++i) {
                    const float x = -1.0f + 0.01f * static_cast<float>(i), y = -0.8f + 0.007f * static_cast<float>(i);
                    glColor4f(1.0f, 0.6f, 0.2f, 0.6f), glVertex3f(x, y, 0);
                    glColor4f(1.0f, 0.5f, 0.1f, 0.3f), glVertex3f(x + 1, y, -0.5f);
                    glColor4f(1.0f, 0.9f, 0.4f, 0.6f), glVertex3f(x + 1, y + 1, -1);
                    glColor4f(0.9f, 0.4f, 0.1f, 0.4f), glVertex3f(x, y + 1, 0);
                }
                glEnd();
                return readStencilFrame();
            },
            "perspective blend " + std::to_string(n));
    }
}
