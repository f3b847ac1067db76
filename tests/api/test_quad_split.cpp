// Filled draws that the reference sends through its draw module with no vertex to clip (polygon
// stipple; a polygon offset with line stipple, smooth lines or smooth points): their quads split
// along v1-v3 and their quad strips' triangles come in the draw module's order. Every case is
// compared with a live OSMesa render, colour and depth (docs/probes/quad_split_probe.cpp).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kSize = 32;

enum class Prim { Quads, QuadStrip, FoldedQuadStrip, Rect };

struct StateCase {
    const char* name;
    void (*set)();
};

void offsetFill() {
    glPolygonOffset(1.5f, 4.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
}

void lineStipple(GLushort pattern) {
    glLineStipple(1, pattern);
    glEnable(GL_LINE_STIPPLE);
}

const StateCase kStates[] = {
    {"plain", [] {}},
    {"polygon stipple", [] { glEnable(GL_POLYGON_STIPPLE); }},
    {"polygon stipple with a pattern",
     [] {
         GLubyte pattern[128];
         for (int i = 0; i < 128; ++i) pattern[i] = static_cast<GLubyte>(i % 8 < 4 ? 0xB7 : 0x6D);
         glPolygonStipple(pattern);
         glEnable(GL_POLYGON_STIPPLE);
     }},
    {"polygon stipple + offset fill",
     [] {
         glEnable(GL_POLYGON_STIPPLE);
         offsetFill();
     }},
    {"offset fill + line stipple 0x5555",
     [] {
         offsetFill();
         lineStipple(0x5555);
     }},
    {"offset fill + line stipple 0",
     [] {
         offsetFill();
         lineStipple(0);
     }},
    {"offset fill + line stipple 0xffff (direct)",
     [] {
         offsetFill();
         lineStipple(0xFFFF);
     }},
    {"offset fill + line smooth",
     [] {
         offsetFill();
         glEnable(GL_LINE_SMOOTH);
     }},
    {"offset fill + point smooth",
     [] {
         offsetFill();
         glEnable(GL_POINT_SMOOTH);
     }},
    {"offset line + line stipple",
     [] {
         glPolygonOffset(1.5f, 4.0f);
         glEnable(GL_POLYGON_OFFSET_LINE);
         lineStipple(0x0F0F);
     }},
    {"line stipple alone (direct)", [] { lineStipple(0x5555); }},
    {"line smooth alone (direct)", [] { glEnable(GL_LINE_SMOOTH); }},
    {"polygon stipple + cull back",
     [] {
         glEnable(GL_POLYGON_STIPPLE);
         glEnable(GL_CULL_FACE);
     }},
};

// Depth near at v0 and v2, far at v1 and v3, and red at v0 and v2 only: either split shows.
const GLfloat kCorner[4][3] = {{3, 2, 0.5f}, {29, 5, -0.5f}, {27, 30, 0.7f}, {2, 26, -0.3f}};

void vertex(int i, bool ownColors) {
    if (ownColors) glColor3f(i % 2 == 0 ? 1.0f : 0.1f, 0.3f + 0.2f * static_cast<GLfloat>(i), 0.5f);
    glVertex3fv(kCorner[i]);
}

Frame draw(Prim prim, const StateCase& state, bool flat, bool ownColors) {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kSize, 0, kSize, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    state.set();
    glColor3f(0.9f, 0.8f, 0.7f);
    switch (prim) {
    case Prim::Quads:
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; ++i) vertex(i, ownColors);
        glEnd();
        break;
    case Prim::QuadStrip:
        glBegin(GL_QUAD_STRIP);
        for (int i : {0, 1, 3, 2}) vertex(i, ownColors);
        glEnd();
        break;
    case Prim::FoldedQuadStrip:
        // A bow tie: its two triangles overlap, so the order they are drawn in shows.
        glBegin(GL_QUAD_STRIP);
        for (int i : {0, 1, 2, 3}) vertex(i, ownColors);
        glEnd();
        break;
    case Prim::Rect: {
        // Eye z = x + 0.5 y: the linear fog of |z| is not planar over the rect, so its split shows.
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-1.2, 1.2, -1.2, 1.2, -3, 3);
        glMatrixMode(GL_MODELVIEW);
        const GLfloat tilt[16] = {1, 0, 1, 0, 0, 1, 0.5f, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        glLoadMatrixf(tilt);
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, 0);
        glFogf(GL_FOG_END, 2);
        glRectf(-1, -1, 1, 1);
        break;
    }
    }
    return readFrame(kSize, kSize);
}

// How many pixels differ in colour and in depth.
std::string differingPixels(const Frame& a, const Frame& b) {
    int colors = 0, depths = 0;
    for (std::size_t i = 0; i < a.depth.size(); ++i) {
        depths += a.depth[i] != b.depth[i];
        for (std::size_t c = 0; c < 4; ++c) {
            if (a.color[i * 4 + c] != b.color[i * 4 + c]) {
                ++colors;
                break;
            }
        }
    }
    return std::to_string(colors) + " colour, " + std::to_string(depths) + " depth";
}

TEST(QuadSplit, DrawModuleFillsSplitQuadsAsTheReference) {
    const char* const primNames[] = {"GL_QUADS", "GL_QUAD_STRIP", "folded GL_QUAD_STRIP", "glRect under fog"};
    for (Prim prim : {Prim::Quads, Prim::QuadStrip, Prim::FoldedQuadStrip, Prim::Rect})
        for (const StateCase& state : kStates)
            for (bool flat : {false, true})
                for (bool own : {false, true}) {
                    if (prim == Prim::Rect && own) continue;
                    const auto frames =
                        onBothBackends<Frame>([&] { return draw(prim, state, flat, own); }, kSize, kSize);
                    EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), "0 colour, 0 depth")
                        << primNames[static_cast<int>(prim)] << ", " << state.name << (flat ? ", flat" : ", smooth")
                        << (own ? ", own colours" : ", one colour");
                }
}

// Whether MyGL and OSMesa draw the same 300 slivers in a 64x64 window, each with its third
// vertex within 0.0005 pixels of the line through the other two (where the draw module's float
// determinant and setup's fixed-point area disagree), drawn as GL_TRIANGLES after `set`.
bool sliversDrawnAlike(std::mt19937& random, const std::function<void()>& set) {
    std::uniform_real_distribution<float> position(0, 64), nudge(-0.0005f, 0.0005f), unit(0, 1);
    std::vector<GLfloat> slivers;  // x0 y0 x1 y1 x2 y2 r g b
    for (int i = 0; i < 300; ++i) {
        const GLfloat x0 = position(random), y0 = position(random), x1 = position(random), y1 = position(random),
                      t = unit(random);
        const GLfloat x2 = x0 + (x1 - x0) * t + nudge(random), y2 = y0 + (y1 - y0) * t + nudge(random);
        slivers.insert(slivers.end(), {x0, y0, x1, y1, x2, y2, unit(random), unit(random), unit(random)});
    }
    const auto frames = onBothBackends<Frame>(
        [&] {
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glMatrixMode(GL_PROJECTION);
            glLoadIdentity();
            glOrtho(0, 64, 0, 64, -1, 1);
            set();
            glBegin(GL_TRIANGLES);
            for (std::size_t i = 0; i < slivers.size(); i += 9) {
                glColor3fv(&slivers[i + 6]);
                for (std::size_t v = 0; v < 3; ++v) glVertex2fv(&slivers[i + 2 * v]);
            }
            glEnd();
            return readFrame(64, 64);
        },
        64, 64);
    return frames.mygl == frames.osmesa;
}

// The draw module's cull stage decides by its float determinant before setup's area. Culled by
// setup's area alone, 17 of these 24 frames differed.
TEST(QuadSplit, DrawModuleFillsAreCulledByTheDrawModule) {
    std::mt19937 random(7);
    for (const StateCase* state : {&kStates[1], &kStates[8]}) {
        for (int frame = 0; frame < 12; ++frame) {
            EXPECT_TRUE(sliversDrawnAlike(random,
                                          [&] {
                                              glEnable(GL_CULL_FACE);
                                              state->set();
                                          }))
                << state->name << ", frame " << frame;
        }
    }
}

// With two-sided lighting the draw module's two-sided stage picks the back colours by its
// determinant (not 0), not setup's area: all 16 frames differed by the area.
TEST(QuadSplit, DrawModuleFillsTakeTheirBackColoursByTheDrawModule) {
    std::mt19937 random(11);
    for (int frame = 0; frame < 16; ++frame) {
        EXPECT_TRUE(sliversDrawnAlike(random,
                                      [] {
                                          glEnable(GL_LIGHTING);
                                          glEnable(GL_LIGHT0);
                                          glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                                          const GLfloat front[] = {1, 0, 0, 1}, back[] = {0, 0, 1, 1};
                                          glMaterialfv(GL_FRONT, GL_DIFFUSE, front);
                                          glMaterialfv(GL_BACK, GL_DIFFUSE, back);
                                          glNormal3f(0, 0, 1);
                                          glEnable(GL_POLYGON_STIPPLE);
                                      }))
            << "frame " << frame;
    }
}

}  // namespace
