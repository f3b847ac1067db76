// Vertex arrays: meshes drawn with glDrawArrays, glDrawElements and glArrayElement from
// arrays of every layout, compared with OSMesa running the very same calls, colours and depth
// bit for bit; the array state, queries and errors likewise. The reference converts the quads of
// glDrawElements into (0,1,3), (1,2,3) triangles before drawing, those of glDrawArrays not.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 80, kHeight = 60;

void perspectiveView() {
    testing_support::clearedPerspectiveView(5.0f);
    glRotatef(30.0f, 1.0f, 0.6f, 0.1f);
}

// A cube's 8 corners with a colour each, and its faces as quads and as triangles.
const GLfloat kCorners[8 * 3] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
const GLubyte kCornerColors[8 * 4] = {255, 0, 0,   255, 0, 255, 0,   255, 0,   0,   255, 255, 255, 255, 0,  255,
                                      255, 0, 255, 255, 0, 255, 255, 255, 128, 128, 128, 255, 30,  200, 90, 255};
const GLushort kQuadIndices[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 0, 4, 7, 3};

// An interleaved layout as programs write it: a struct per vertex.
struct PackedVertex {
    GLfloat position[3];
    GLubyte color[4];
    GLshort texCoord[2];
};

// A strip along a wave, 2 * n vertices.
std::vector<PackedVertex> wave(int n) {
    std::vector<PackedVertex> v;
    for (int i = 0; i < n; ++i) {
        const float x = -1.6f + 3.2f * static_cast<float>(i) / static_cast<float>(n - 1);
        const float z = 0.6f * std::sin(3.0f * x);
        const auto c = static_cast<GLubyte>(255 * i / (n - 1));
        v.push_back({{x, -0.8f, z}, {c, 80, static_cast<GLubyte>(255 - c), 255}, {1, 0}});
        v.push_back({{x, 0.9f, -z}, {80, c, 200, 255}, {0, 1}});
    }
    return v;
}

}  // namespace

TEST(VertexArrays, DrawArraysAndDrawElementsOfEveryModeMatchTheReference) {
    const std::vector<PackedVertex> strip = wave(12);
    const std::pair<const char*, std::function<void()>> draws[] = {
        {"quads by index", [] { glDrawElements(GL_QUADS, 24, GL_UNSIGNED_SHORT, kQuadIndices); }},
        {"quads", [&] { glDrawArrays(GL_QUADS, 0, static_cast<GLsizei>(strip.size())); }},
        {"triangle strip", [&] { glDrawArrays(GL_TRIANGLE_STRIP, 0, static_cast<GLsizei>(strip.size())); }},
        {"quad strip from the third vertex",
         [&] { glDrawArrays(GL_QUAD_STRIP, 2, static_cast<GLsizei>(strip.size()) - 2); }},
        {"line loop", [&] { glDrawArrays(GL_LINE_LOOP, 0, 9); }},
        {"points",
         [&] {
             glPointSize(2);
             glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(strip.size()));
         }},
        {"triangles by byte index",
         [] {
             const GLubyte indices[] = {0, 1, 2, 2, 3, 0, 4, 6, 5};
             glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, indices);
         }},
        {"polygon by int index",
         [] {
             const GLuint indices[] = {4, 5, 6, 7};
             glDrawElements(GL_POLYGON, 4, GL_UNSIGNED_INT, indices);
         }},
    };
    for (const auto& [name, draw] : draws) {
        const bool cube = std::strstr(name, "index") != nullptr;
        const auto frames = onBothBackends<Frame>(
            [&] {
                perspectiveView();
                glEnableClientState(GL_VERTEX_ARRAY);
                glEnableClientState(GL_COLOR_ARRAY);
                if (cube) {
                    glVertexPointer(3, GL_FLOAT, 0, kCorners);
                    glColorPointer(4, GL_UNSIGNED_BYTE, 0, kCornerColors);
                } else {
                    glVertexPointer(3, GL_FLOAT, sizeof(PackedVertex), strip[0].position);
                    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(PackedVertex), strip[0].color);
                }
                draw();
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(frames.mygl.color, frames.osmesa.color) << name;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << name;
    }
}

TEST(VertexArrays, ArrayElementInsideBeginEndAndTheCurrentColorAsAConstant) {
    const std::vector<PackedVertex> strip = wave(7);
    const auto frames = onBothBackends<Frame>(
        [&] {
            perspectiveView();
            glEnableClientState(GL_VERTEX_ARRAY);
            glVertexPointer(3, GL_FLOAT, sizeof(PackedVertex), strip[0].position);
            glColor3f(0.9f, 0.6f, 0.2f);  // no colour array: one colour for the draw
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 6);
            glEnableClientState(GL_COLOR_ARRAY);
            glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(PackedVertex), strip[0].color);
            glBegin(GL_TRIANGLES);
            for (GLint i = 6; i < 12; ++i) glArrayElement(i);
            glEnd();
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_EQ(frames.mygl.color, frames.osmesa.color);
    EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth);
}

TEST(VertexArrays, EveryInterleavedFormatDrawsAsTheReference) {
    // 4 vertices of up to 15 floats (T4F C4F N3F V4F); colour bytes where the format has them.
    std::vector<GLfloat> data(4 * 15);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = 0.3f + 0.1f * static_cast<float>(i % 7);
    const GLenum formats[] = {GL_V2F,         GL_V3F,         GL_C4UB_V2F,        GL_C4UB_V3F,       GL_C3F_V3F,
                              GL_N3F_V3F,     GL_C4F_N3F_V3F, GL_T2F_V3F,         GL_T4F_V4F,        GL_T2F_C4UB_V3F,
                              GL_T2F_C3F_V3F, GL_T2F_N3F_V3F, GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F};
    for (GLenum format : formats) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                glClear(GL_COLOR_BUFFER_BIT);
                glInterleavedArrays(format, 15 * sizeof(GLfloat), data.data());
                glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(frames.mygl.color, frames.osmesa.color) << std::hex << format;
    }
}

TEST(VertexArrays, AListKeepsTheArrayDataOfWhenItWasCompiled) {
    const auto frames = onBothBackends<Frame>(
        [&] {
            std::vector<PackedVertex> strip = wave(8);  // each backend its own, changed below
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_COLOR_ARRAY);
            glVertexPointer(3, GL_FLOAT, sizeof(PackedVertex), strip[0].position);
            glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(PackedVertex), strip[0].color);
            glNewList(1, GL_COMPILE);
            glDrawArrays(GL_QUAD_STRIP, 0, 16);
            glDrawElements(GL_QUADS, 24, GL_UNSIGNED_SHORT, kQuadIndices);
            glBegin(GL_POINTS);
            glArrayElement(3);
            glEnd();
            glEndList();
            for (PackedVertex& v : strip) v.position[1] += 5.0f;  // the list drew before this
            perspectiveView();
            glCallList(1);
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_EQ(frames.mygl.color, frames.osmesa.color);
    EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth);
}

TEST(VertexArrays, StateQueriesAndCurrentValuesAnswerAsTheReference) {
    const auto answers = onBothBackends<std::vector<GLfloat>>([] {
        static const GLshort positions[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        static const GLfloat colors[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};
        glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
        glVertexPointer(2, GL_SHORT, 4, positions);
        glColorPointer(3, GL_FLOAT, 0, colors);
        glTexCoordPointer(1, GL_DOUBLE, 16, positions);
        glNormalPointer(GL_BYTE, 3, colors);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
        std::vector<GLfloat> a(4);
        glGetFloatv(GL_CURRENT_COLOR, a.data());  // unchanged by the draw
        for (GLenum name :
             {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE,
              GL_VERTEX_ARRAY_STRIDE, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
              GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
              GL_TEXTURE_COORD_ARRAY_STRIDE, GL_EDGE_FLAG_ARRAY_STRIDE, GL_INDEX_ARRAY_TYPE}) {
            GLint value = -1;
            glGetIntegerv(name, &value);
            a.push_back(static_cast<GLfloat>(value));
        }
        a.push_back(glIsEnabled(GL_COLOR_ARRAY));
        void* pointer = nullptr;
        glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer);
        a.push_back(pointer == positions ? 1.0f : 0.0f);
        glGetPointerv(GL_NORMAL_ARRAY_POINTER, &pointer);
        a.push_back(pointer == colors ? 1.0f : 0.0f);
        glDisableClientState(GL_COLOR_ARRAY);
        a.push_back(glIsEnabled(GL_COLOR_ARRAY));
        a.push_back(static_cast<GLfloat>(glGetError()));
        return a;
    });
    EXPECT_EQ(answers.mygl, answers.osmesa);
}

// glDrawElements of many triangles goes to the pipeline in indexed parts (each with the elements
// between its smallest and largest index): a grid of several parts crossing the near plane and
// the sides, culled, in every index type; lit from a normal array; with a part whose indices
// spread wider than their count (a vertex per index); with float and byte colours.
TEST(VertexArrays, LongIndexedTriangleDrawsMatchTheReference) {
    constexpr int kSide = 48;  // 48 x 48 quads: 13824 indices, five parts
    std::vector<GLfloat> positions, normals, colors;
    std::vector<GLubyte> colorBytes;
    for (int j = 0; j <= kSide; ++j) {
        for (int i = 0; i <= kSide; ++i) {
            const float x = -3.0f + 6.0f * static_cast<float>(i) / kSide,
                        y = -3.0f + 6.0f * static_cast<float>(j) / kSide;
            const float h = 0.4f * std::sin(2.0f * x) * std::cos(1.5f * y);
            positions.insert(positions.end(), {x, y, h});
            normals.insert(normals.end(), {-0.8f * std::cos(2.0f * x) * std::cos(1.5f * y),
                                           0.6f * std::sin(2.0f * x) * std::sin(1.5f * y), 1.0f});
            colors.insert(colors.end(), {0.5f + h, 0.4f - h, 0.6f + 2.0f * h});
            colorBytes.insert(colorBytes.end(), {static_cast<GLubyte>(i * 5), static_cast<GLubyte>(j * 5), 140, 255});
        }
    }
    std::vector<GLuint> grid;
    for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) {
            const auto v = static_cast<GLuint>(j * (kSide + 1) + i);
            grid.insert(grid.end(), {v, v + 1, v + kSide + 2, v, v + kSide + 2, v + kSide + 1});
        }
    }
    const std::vector<GLushort> shortGrid(grid.begin(), grid.end());
    // Fans of triangles between the first row and the last: every part spreads over the grid.
    std::vector<GLuint> spread;
    for (GLuint i = 0; i + 1 < kSide; ++i) {
        const GLuint last = kSide * (kSide + 1);
        spread.insert(spread.end(), {i, i + 1, last + i + 1, i, last + i + 1, last + i});
    }
    const GLubyte smallGrid[] = {0, 1, 50, 0, 50, 49, 1, 2, 51, 1, 51, 50, 2, 3};  // an incomplete last triangle
    const std::pair<const char*, std::function<void()>> draws[] = {
        {"uint grid, float colours",
         [&] {
             glColorPointer(3, GL_FLOAT, 0, colors.data());
             glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid.size()), GL_UNSIGNED_INT, grid.data());
         }},
        {"ushort grid, byte colours",
         [&] {
             glColorPointer(4, GL_UNSIGNED_BYTE, 0, colorBytes.data());
             glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(shortGrid.size()), GL_UNSIGNED_SHORT, shortGrid.data());
         }},
        {"spread indices",
         [&] {
             glColorPointer(3, GL_FLOAT, 0, colors.data());
             glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(spread.size()), GL_UNSIGNED_INT, spread.data());
         }},
        {"ubyte indices",
         [&] {
             glColorPointer(3, GL_FLOAT, 0, colors.data());
             glDrawElements(GL_TRIANGLES, 14, GL_UNSIGNED_BYTE, smallGrid);
         }},
        {"lit grid",
         [&] {
             glDisableClientState(GL_COLOR_ARRAY);
             glEnableClientState(GL_NORMAL_ARRAY);
             glNormalPointer(GL_FLOAT, 0, normals.data());
             const GLfloat position[] = {1.0f, 2.0f, 3.0f, 0.0f}, specular[] = {0.6f, 0.6f, 0.6f, 1.0f};
             glLightfv(GL_LIGHT0, GL_POSITION, position);
             glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
             glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
             glEnable(GL_LIGHTING);
             glEnable(GL_LIGHT0);
             glEnable(GL_NORMALIZE);
             glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(grid.size()), GL_UNSIGNED_INT, grid.data());
         }},
    };
    for (const auto& [name, draw] : draws) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                testing_support::clearedPerspectiveView(2.2f);
                glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
                glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
                glEnable(GL_CULL_FACE);
                glEnableClientState(GL_VERTEX_ARRAY);
                glEnableClientState(GL_COLOR_ARRAY);
                glVertexPointer(3, GL_FLOAT, 0, positions.data());
                draw();
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(frames.mygl.color, frames.osmesa.color) << name;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << name;
    }
}
