// The accumulation buffer: glAccum sequences over drawn scenes, glClearAccum values, its queries,
// attribute group, errors and display lists, each compared with OSMesa running the same calls.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::difference;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 64, kHeight = 48;

// Smooth triangles over a grey background, shifted by a sub-pixel offset (the jitter of an
// antialiasing pass).
void jitteredScene(float dx, float dy) {
    glClearColor(0.25f, 0.25f, 0.3f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(dx, dy, 0);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0.1f, 0.1f, 1);
    glVertex2f(3, 4);
    glColor4f(0.1f, 1, 0.2f, 0.7f);
    glVertex2f(60, 10);
    glColor4f(0.2f, 0.3f, 1, 0.2f);
    glVertex2f(20, 45);
    glColor4f(1, 1, 1, 1);
    glVertex2f(40, 40);
    glVertex2f(62, 30);
    glVertex2f(55, 47);
    glEnd();
}

struct Step {
    GLenum op;  // 0: draw the scene with the jitter (value, value / 2); GL_ACCUM_BUFFER_BIT: clear it
    // (its contents are undefined until then: the reference's are not zero)
    float value;
};

std::string describe(const std::vector<Step>& steps) {
    std::string text;
    for (const Step& s : steps)
        text += (s.op ? std::to_string(s.op) : std::string("draw")) + "(" + std::to_string(s.value) + ") ";
    return text;
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

TEST(Accumulation, OperationSequencesMatchTheReferenceBitForBit) {
    const std::vector<std::vector<Step>> sequences = {
        {{0, 0}, {GL_LOAD, 1}, {GL_RETURN, 1}},
        {{GL_ACCUM_BUFFER_BIT, 0},
         {0, 0},
         {GL_ACCUM, 0.25f},
         {0, 0.5f},
         {GL_ACCUM, 0.25f},
         {0, 0.25f},
         {GL_ACCUM, 0.25f},
         {0, 0.75f},
         {GL_ACCUM, 0.25f},
         {GL_RETURN, 1}},
        {{0, 0}, {GL_LOAD, 1.0f / 3}, {0, 0.3f}, {GL_ACCUM, 1.0f / 3}, {0, 0.6f}, {GL_ACCUM, 1.0f / 3}, {GL_RETURN, 1}},
        {{0, 0}, {GL_LOAD, 0.5f}, {GL_MULT, 0.7f}, {GL_ADD, 0.1f}, {GL_RETURN, 1.5f}},
        {{0, 0}, {GL_LOAD, 0.9f}, {0, 0.4f}, {GL_ACCUM, 0.9f}, {GL_RETURN, 0.5f}},  // the words overflow
        {{0, 0}, {GL_LOAD, 1}, {GL_MULT, 3}, {GL_RETURN, 1}},
        {{0, 0}, {GL_LOAD, 1}, {GL_ADD, -0.6f}, {GL_RETURN, 2}},
        {{0, 0}, {GL_LOAD, -1}, {GL_RETURN, -1}},
        {{0, 0}, {GL_LOAD, 0.8f}, {GL_RETURN, 0.1f}, {0, 0.5f}, {GL_RETURN, 1}},  // RETURN keeps the buffer
        {{0, 0}, {GL_LOAD, 1}, {GL_MULT, 1e12f}, {GL_RETURN, 1}},
        {{0, 0}, {GL_LOAD, kNaN}, {GL_ADD, kInf}, {GL_RETURN, 1}},
        {{0, 0}, {GL_LOAD, 1}, {GL_MULT, kNaN}, {GL_RETURN, kInf}},
        {{0, 0}, {GL_LOAD, 1}, {GL_RETURN, kNaN}},
    };
    for (const auto& steps : sequences) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                for (const Step& s : steps) {
                    if (s.op == 0)
                        jitteredScene(s.value, s.value / 2);
                    else if (s.op == GL_ACCUM_BUFFER_BIT)
                        glClear(GL_ACCUM_BUFFER_BIT);
                    else
                        glAccum(s.op, s.value);
                }
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        const auto d = difference(frames.mygl, frames.osmesa);
        EXPECT_EQ(d.pixels, 0) << describe(steps) << ": max channel difference " << d.maxChannel;
    }
}

TEST(Accumulation, ClearValuesMatchTheReference) {
    const std::vector<std::array<float, 4>> values = {
        {0, 0, 0, 0},
        {1, 0.5f, 0.25f, 0.125f},
        {-0.3f, 0.7f, 0.999f, 0.001f},
        {2, -3, 1.5f, -0.5f},
        {1.0f / 255, 0.5f / 255, 254.5f / 255, 0.3333f},
        {kNaN, kInf, -kInf, 0.6f},
    };
    for (const auto& v : values) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                glClearAccum(v[0], v[1], v[2], v[3]);
                glClear(GL_ACCUM_BUFFER_BIT);
                glAccum(GL_RETURN, 1);
                glAccum(GL_ACCUM, 0.5f);  // adds the (black) colour buffer's half
                glClearColor(0.5f, 0.2f, 0.9f, 1);
                glClear(GL_COLOR_BUFFER_BIT);
                glAccum(GL_ACCUM, -0.25f);
                glAccum(GL_RETURN, 2);
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(difference(frames.mygl, frames.osmesa).pixels, 0)
            << v[0] << " " << v[1] << " " << v[2] << " " << v[3];
    }
}

// The scissor box narrows every operation and the accumulation buffer's clear; GL_RETURN writes
// through the colour mask.
TEST(Accumulation, ScissorAndColorMaskApplyAsInTheReference) {
    const auto frames = onBothBackends<Frame>(
        [&] {
            jitteredScene(0, 0);
            glClearAccum(0.1f, 0.5f, 0.9f, 0.3f);
            glClear(GL_ACCUM_BUFFER_BIT);
            glEnable(GL_SCISSOR_TEST);
            glScissor(5, 9, 40, 20);
            glAccum(GL_ACCUM, 0.5f);
            glClearAccum(0.7f, 0.1f, 0.2f, 0.5f);
            glScissor(20, 2, 30, 40);
            glClear(GL_ACCUM_BUFFER_BIT);
            glScissor(3, 6, 50, 30);
            glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
            glAccum(GL_RETURN, 1.0f);
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_EQ(difference(frames.mygl, frames.osmesa).pixels, 0);
}

// Everything that is not a frame: queries, the attribute group, errors, display lists, and no
// effect outside GL_RENDER. Each line is a value or an error, compared as a whole.
std::vector<double> accumStateWalk() {
    std::vector<double> out;
    const auto error = [&] { out.push_back(glGetError()); };
    const auto getAll = [&](GLenum name, int count) {
        GLfloat f[4] = {};
        GLint i[4] = {};
        GLboolean b[4] = {};
        glGetFloatv(name, f);
        glGetIntegerv(name, i);
        glGetBooleanv(name, b);
        for (int k = 0; k < count; ++k) out.insert(out.end(), {f[k], double(i[k]), double(b[k])});
        error();
    };
    for (GLenum bits : {GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS, GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS})
        getAll(bits, 1);
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    glClearAccum(0.5f, -0.25f, 3, -7);
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    glPushAttrib(GL_ACCUM_BUFFER_BIT);
    glClearAccum(0.1f, 0.2f, 0.3f, 0.4f);
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    glPopAttrib();
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_ACCUM_BUFFER_BIT);
    glClearAccum(0.1f, 0.2f, 0.3f, 0.4f);
    glPopAttrib();
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    glAccum(GL_ZERO, 1);
    error();
    glAccum(GL_LOAD + 5, 1);
    error();
    glBegin(GL_TRIANGLES);
    glAccum(GL_LOAD, 1);
    glClearAccum(1, 1, 1, 1);
    glEnd();
    error();
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    // Compiled, not executed, errors only when the list runs.
    glNewList(1, GL_COMPILE);
    glClearAccum(0.75f, 0.5f, 0.25f, 1);
    glAccum(GL_ZERO, 1);
    glEndList();
    error();
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    glCallList(1);
    error();
    getAll(GL_ACCUM_CLEAR_VALUE, 4);
    // A frame: the list's clear value returned, then nothing done in GL_SELECT.
    GLuint hits[16];
    glClear(GL_ACCUM_BUFFER_BIT);
    glSelectBuffer(16, hits);
    glRenderMode(GL_SELECT);
    glAccum(GL_ADD, 0.5f);
    glClear(GL_ACCUM_BUFFER_BIT);
    glRenderMode(GL_RENDER);
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glAccum(GL_RETURN, 1);
    glEndList();
    GLubyte pixel[4];
    glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    out.insert(out.end(), {double(pixel[0]), double(pixel[1]), double(pixel[2]), double(pixel[3])});
    error();
    return out;
}

TEST(Accumulation, QueriesAttribGroupErrorsAndListsMatchTheReference) {
    const auto walks = onBothBackends<std::vector<double>>(accumStateWalk);
    EXPECT_EQ(testing_support::firstDifference(walks.mygl, walks.osmesa), "");
}

}  // namespace
