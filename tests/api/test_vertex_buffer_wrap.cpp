// Where the reference's immediate-mode vertex buffer fills up and wraps, a long primitive is
// drawn in parts, and whether a part needs clipping decides how its quads are split (issue 12,
// item 8). The wrap point depends on the vertex format (the attributes used since the last
// flush) and on how much of the 512 KiB buffer earlier draws used, in this frame or earlier
// ones. Each case draws points outside the window first, to leave only a little room, then a
// primitive that crosses the window's edge late; compared with OSMesa bit for bit, depth too.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kSize = 64;

// Uses `count` vertices of 8 bytes of the reference's buffer, drawing nothing, and flushes.
void useBuffer(int count) {
    glBegin(GL_POINTS);
    for (int i = 0; i < count; ++i) glVertex2f(5.0f, 5.0f);
    glEnd();
    glFlush();
}

// A repeatable value in [0, 1) for vertex i, component k.
float wave(int i, int k) { return 0.5f + 0.5f * std::sin(static_cast<float>(i * 7 + k * 13) * 0.37f); }

// Vertex i of a run of non-planar quads on an 8 x 8 grid of cells, row by row; the cells of the
// last row reach past the right edge of the window.
void gridVertex(int i, int positionSize) {
    const int quad = i / 4, corner = i % 4;
    const float cell = 2.0f / 8.0f;
    const float x0 = -1.0f + cell * static_cast<float>(quad % 8), y0 = -1.0f + cell * static_cast<float>(quad / 8 % 8);
    const float dx = corner == 1 || corner == 2 ? cell : 0.0f, dy = corner >= 2 ? cell : 0.0f;
    const float stretch = quad / 8 % 8 == 7 ? 1.6f : 1.0f;
    const float x = (x0 + dx) * stretch, y = y0 + dy, z = wave(i, 3) - 0.5f;
    if (positionSize == 2)
        glVertex2f(x, y);
    else if (positionSize == 3)
        glVertex3f(x, y, z);
    else
        glVertex4f(x, y, z, 1.0f);
}

void expectSameFrames(const std::function<void()>& calls, const char* what) {
    const auto frames = onBothBackends<Frame>(
        [&] {
            glEnable(GL_DEPTH_TEST);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            calls();
            return readFrame(kSize, kSize);
        },
        kSize, kSize);
    EXPECT_EQ(frames.mygl.color, frames.osmesa.color) << what;
    EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << what;
}

}  // namespace

TEST(VertexBufferWrap, QuadRunsSplitWhereTheReferenceBufferFills) {
    struct Format {
        int positionSize;
        int colorSize;  // 0: one color for the draw; 3: glColor3f; 4: glColor4f
        bool normal, texCoord, edgeFlag, integerColor;
    };
    const Format formats[] = {{2, 3, false, false, false, false},
                              {3, 4, false, false, false, false},
                              {4, 3, true, false, false, true},
                              {3, 0, false, true, true, false},
                              {3, 3, true, true, false, false}};
    // Points before the quads, for wrap points at different places in a quad and in the grid.
    const int usedVertices[] = {64900, 65000, 65100, 65200, 65250};
    for (const Format& format : formats) {
        for (const int used : usedVertices) {
            expectSameFrames(
                [&] {
                    useBuffer(used);
                    glBegin(GL_QUADS);
                    for (int i = 0; i < 4 * 64; ++i) {
                        if (format.colorSize == 4) glColor4f(wave(i, 0), wave(i, 1), wave(i, 2), 1.0f);
                        if (format.colorSize == 3 && format.integerColor)
                            glColor3ub(static_cast<GLubyte>(wave(i, 0) * 255), 40,
                                       static_cast<GLubyte>(wave(i, 2) * 255));
                        else if (format.colorSize == 3)
                            glColor3f(wave(i, 0), wave(i, 1), wave(i, 2));
                        if (format.normal) glNormal3f(0, 0, 1);
                        if (format.texCoord) glTexCoord2f(wave(i, 4), wave(i, 5));
                        if (format.edgeFlag) glEdgeFlag(GL_TRUE);
                        gridVertex(i, format.positionSize);
                    }
                    glEnd();
                },
                ("position " + std::to_string(format.positionSize) + " color " + std::to_string(format.colorSize) +
                 " after " + std::to_string(used))
                    .c_str());
        }
    }
}

TEST(VertexBufferWrap, EarlierFramesAndBlocksCount) {
    // The buffer is used up across glClear and frames; merged blocks wrap like one.
    expectSameFrames(
        [] {
            useBuffer(40000);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            useBuffer(25000);
            for (int block = 0; block < 16; ++block) {
                glBegin(GL_QUADS);
                for (int i = block * 16; i < block * 16 + 16; ++i) {
                    glColor3f(wave(i, 0), wave(i, 1), wave(i, 2));
                    gridVertex(i, 3);
                }
                glEnd();
            }
        },
        "blocks");
}

TEST(VertexBufferWrap, AnAttributeNewInTheFormatEndsTheDraw) {
    // The first glNormal inside a later block widens the reference's vertices: what it held is
    // drawn first, so the quads before it take the direct path's diagonal.
    expectSameFrames(
        [] {
            glBegin(GL_QUADS);
            for (int i = 0; i < 4 * 40; ++i) {
                glColor3f(wave(i, 0), wave(i, 1), wave(i, 2));
                gridVertex(i, 3);
            }
            glEnd();
            glBegin(GL_QUADS);
            for (int i = 4 * 40; i < 4 * 64; ++i) {
                if (i == 4 * 40 + 2) glNormal3f(0, 0, 1);
                glColor3f(wave(i, 0), wave(i, 1), wave(i, 2));
                gridVertex(i, 3);
            }
            glEnd();
        },
        "normal");
}

TEST(VertexBufferWrap, StripsFansAndPolygonsGoOnInTheNextPart) {
    const GLenum modes[] = {GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_POLYGON,   GL_QUAD_STRIP,
                            GL_LINE_STRIP,     GL_LINE_LOOP,    GL_TRIANGLES, GL_LINES};
    for (const GLenum mode : modes) {
        for (const int used : {65300, 65301, 65302}) {
            expectSameFrames(
                [&] {
                    glEnable(GL_CULL_FACE);
                    useBuffer(used);
                    glBegin(mode);
                    for (int i = 0; i < 200; ++i) {
                        // A zigzag spiral: strips fold, fans and polygons turn around.
                        const float angle = static_cast<float>(i) * 0.21f, radius = 0.15f + 0.9f * wave(i, 6);
                        glColor3f(wave(i, 0), wave(i, 1), wave(i, 2));
                        glVertex3f(radius * std::cos(angle) * 1.3f, radius * std::sin(angle), wave(i, 3) - 0.5f);
                    }
                    glEnd();
                },
                ("mode " + std::to_string(mode) + " after " + std::to_string(used)).c_str());
        }
    }
}

TEST(VertexBufferWrap, LongLineLoopsCloseOnTheirFirstVertex) {
    // 70000 vertices of 12 bytes wrap once: after vertex 43688 in a new buffer, after 37022
    // when 10000 points came first (for a second wrap see the next test).
    for (const int used : {0, 10000}) {
        expectSameFrames(
            [&] {
                if (used > 0) useBuffer(used);
                glBegin(GL_LINE_LOOP);
                for (int i = 0; i < 70000; ++i) {
                    // Inside the window until the last few hundred vertices, which cross its edge:
                    // only the draws of the last part go through the clipper.
                    const float angle = static_cast<float>(i) * 0.0137f, reach = i > 69700 ? 1.3f : 0.95f;
                    glVertex3f(reach * std::cos(angle) * wave(i, 1), 0.95f * std::sin(angle * 1.01f),
                               wave(i, 2) - 0.5f);
                }
                glEnd();
            },
            used > 0 ? "after points" : "new buffer");
    }
}

// A reference departure: when a GL_LINE_LOOP wraps a second time, the reference copies the
// vertex before the last one to the next part (vbo_copy_vertices steps back over the loop's
// first vertex from an already advanced start), so the segment from the last vertex of the
// part to the next is drawn from the vertex before it instead. MyGL draws the spec's segments:
// what OSMesa draws for the same loop when it wraps only once (the points before it draw nothing).
TEST(VertexBufferWrap, ASecondWrapOfALineLoopKeepsItsSegments) {
    const auto loop = [](bool useBufferFirst) {
        return [=] {
            glClear(GL_COLOR_BUFFER_BIT);
            if (useBufferFirst) useBuffer(65000);
            glBegin(GL_LINE_LOOP);
            // After 65000 points the loop wraps after its vertex 534 and again after 66067.
            for (int i = 0; i < 70000; ++i) {
                if (i == 66066)
                    glVertex2f(-0.9f, 0.9f);
                else if (i == 66067)
                    glVertex2f(0.9f, 0.9f);
                else if (i == 66068)
                    glVertex2f(0.9f, -0.9f);
                else
                    glVertex2f(-0.8f + 0.1f * wave(i, 0), -0.8f + 0.1f * wave(i, 1));
            }
            glEnd();
            return readFrame(kSize, kSize).color;
        };
    };
    const auto twice = onBothBackends<std::vector<GLubyte>>(loop(true), kSize, kSize);
    const auto once = onBothBackends<std::vector<GLubyte>>(loop(false), kSize, kSize);
    EXPECT_EQ(twice.mygl, once.osmesa);
    EXPECT_EQ(once.mygl, once.osmesa);
    EXPECT_NE(twice.osmesa, once.osmesa) << "the reference now keeps the segment: follow it";
}

TEST(VertexBufferWrap, ArrayDrawsUseNoneOfTheBuffer) {
    // glDrawElements and glDrawArrays are drawn from the arrays, not through the immediate-mode
    // buffer: the quads after them wrap where they would without the draw (the draw's 24-byte
    // vertices would fill the little room left several times over). Independent triangles and a
    // strip, which MyGL reads in different ways.
    static GLfloat positions[4 * 3 * 2];
    static GLuint indices[600];
    for (int i = 0; i < 4; ++i) {
        const GLfloat corner[6] = {-0.9f + 0.5f * static_cast<float>(i), -0.9f, 0.2f, 0.3f, 0.6f, 0.9f};
        std::copy(corner, corner + 6, positions + 6 * i);
    }
    for (int i = 0; i < 600; ++i) indices[i] = static_cast<GLuint>(i % 3 + (i / 3) % 2);
    const std::pair<const char*, std::function<void()>> draws[] = {
        {"triangles by index", [] { glDrawElements(GL_TRIANGLES, 600, GL_UNSIGNED_INT, indices); }},
        {"strip by index", [] { glDrawElements(GL_TRIANGLE_STRIP, 600, GL_UNSIGNED_INT, indices); }},
        {"strip", [] { glDrawArrays(GL_TRIANGLE_STRIP, 0, 4); }},
    };
    for (const auto& [name, draw] : draws) {
        for (const int used : {64900, 65100}) {
            expectSameFrames(
                [&] {
                    useBuffer(used);
                    glEnableClientState(GL_VERTEX_ARRAY);
                    glEnableClientState(GL_COLOR_ARRAY);
                    glVertexPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), positions);
                    glColorPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), positions + 3);
                    for (int repeat = 0; repeat < 150; ++repeat) draw();
                    glDisableClientState(GL_COLOR_ARRAY);
                    glDisableClientState(GL_VERTEX_ARRAY);
                    glBegin(GL_QUADS);
                    for (int i = 0; i < 4 * 64; ++i) {
                        glColor3f(wave(i, 0), wave(i, 1), wave(i, 2));
                        gridVertex(i, 3);
                    }
                    glEnd();
                },
                (std::string(name) + " after " + std::to_string(used)).c_str());
        }
    }
}
