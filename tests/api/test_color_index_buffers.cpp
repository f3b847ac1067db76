// The colour-index calls of an RGBA context and glDrawBuffer/glReadBuffer: accepted, kept,
// queried, compiled into lists, with the reference's values and errors; no effect on RGBA pixels
// (draw buffer GL_NONE aside, which clears nothing).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <cmath>
#include <limits>
#include <vector>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

struct Walk {
    std::vector<double> out;
    void error() { out.push_back(glGetError()); }
    void get(GLenum name) {
        GLfloat f = 0;
        GLint i = 0;
        GLboolean b = 0;
        GLdouble d = 0;
        glGetFloatv(name, &f);
        glGetIntegerv(name, &i);
        glGetBooleanv(name, &b);
        glGetDoublev(name, &d);
        out.insert(out.end(), {f, double(i), double(b), d});
        error();
    }
};

std::vector<double> colorIndexWalk() {
    Walk w;
    const GLenum names[] = {GL_CURRENT_INDEX, GL_INDEX_CLEAR_VALUE, GL_INDEX_WRITEMASK,
                            GL_INDEX_BITS,    GL_INDEX_MODE,        GL_RGBA_MODE};
    for (GLenum name : names) w.get(name);
    // (Not beyond the integer range: there glGetIntegerv answers the nearest integer, where the
    // reference keeps the low 32 bits of its lroundf; see BadInput.HugeLineWidth...)
    const float values[] = {2.5f, -1.5f, 0.49f, 7.0f, 2e9f, -2e9f, std::numeric_limits<float>::quiet_NaN()};
    for (float v : values) {
        glIndexf(v);
        w.get(GL_CURRENT_INDEX);
        glClearIndex(v);
        w.get(GL_INDEX_CLEAR_VALUE);
    }
    glIndexd(3.25);
    w.get(GL_CURRENT_INDEX);
    glIndexi(-4);
    w.get(GL_CURRENT_INDEX);
    glIndexs(300);
    w.get(GL_CURRENT_INDEX);
    glIndexub(200);
    w.get(GL_CURRENT_INDEX);
    const GLdouble dv = 5.5;
    glIndexdv(&dv);
    w.get(GL_CURRENT_INDEX);
    const GLfloat fv = 6.5f;
    glIndexfv(&fv);
    w.get(GL_CURRENT_INDEX);
    const GLint iv = 9;
    glIndexiv(&iv);
    w.get(GL_CURRENT_INDEX);
    const GLshort sv = -2;
    glIndexsv(&sv);
    w.get(GL_CURRENT_INDEX);
    const GLubyte ubv = 17;
    glIndexubv(&ubv);
    w.get(GL_CURRENT_INDEX);
    for (GLuint mask : {0u, 5u, 0xFFFFFFFFu, 0x80000000u}) {
        glIndexMask(mask);
        w.get(GL_INDEX_WRITEMASK);
    }
    // glIndex is allowed between glBegin and glEnd; glClearIndex and glIndexMask are not.
    glBegin(GL_POINTS);
    glIndexf(11);
    glClearIndex(4);
    glIndexMask(3);
    glEnd();
    w.error();
    for (GLenum name : names) w.get(name);
    // Attribute groups: the current index with GL_CURRENT_BIT, the clear index and mask with
    // GL_COLOR_BUFFER_BIT.
    glPushAttrib(GL_CURRENT_BIT | GL_COLOR_BUFFER_BIT);
    glIndexf(1);
    glClearIndex(2);
    glIndexMask(7);
    glPopAttrib();
    for (GLenum name : names) w.get(name);
    // (glClearIndex in a list: see ClearIndexInAListKeepsItsValue.)
    glNewList(1, GL_COMPILE);
    glIndexf(21);
    glIndexMask(23);
    glEndList();
    for (GLenum name : names) w.get(name);
    glCallList(1);
    for (GLenum name : names) w.get(name);
    return w.out;
}

TEST(ColorIndex, CallsAreKeptAndQueriedAsTheReferenceDoes) {
    const auto walks = onBothBackends<std::vector<double>>(colorIndexWalk);
    EXPECT_EQ(testing_support::firstDifference(walks.mygl, walks.osmesa), "");
}

// A departure from the reference: its display list replays glClearIndex(c) with the float's bits
// read as an unsigned integer (22.0f comes back as 1102053376); GL keeps the value.
TEST(ColorIndex, ClearIndexInAListKeepsItsValue) {
    mygl::Context context(4, 4);
    context.makeCurrent();
    glNewList(1, GL_COMPILE);
    glClearIndex(22);
    glEndList();
    glCallList(1);
    GLint value = 0;
    glGetIntegerv(GL_INDEX_CLEAR_VALUE, &value);
    EXPECT_EQ(value, 22);
}

TEST(ColorIndex, CallsChangeNoPixel) {
    const auto frames = onBothBackends<Frame>([] {
        glClearColor(0.2f, 0.4f, 0.6f, 1);
        glClearIndex(5);
        glIndexMask(0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glIndexi(3);
        glColor3f(1, 0.5f, 0);
        glVertex2f(-0.9f, -0.9f);
        glIndexi(4);
        glVertex2f(0.9f, -0.8f);
        glVertex2f(0, 0.9f);
        glEnd();
        return readFrame(16, 16);
    });
    EXPECT_EQ(frames.mygl, frames.osmesa);
}

std::vector<double> bufferWalk() {
    Walk w;
    const GLenum names[] = {GL_DRAW_BUFFER, GL_READ_BUFFER, GL_DOUBLEBUFFER, GL_STEREO, GL_AUX_BUFFERS};
    for (GLenum name : names) w.get(name);
    const GLenum buffers[] = {GL_NONE,       GL_FRONT_LEFT, GL_FRONT_RIGHT, GL_BACK_LEFT, GL_BACK_RIGHT,
                              GL_FRONT,      GL_BACK,       GL_LEFT,        GL_RIGHT,     GL_FRONT_AND_BACK,
                              GL_AUX0,       GL_AUX1,       GL_AUX2,        GL_AUX3,      GL_COLOR_INDEX,
                              GL_TEXTURE_2D, 0x040D,        0x03FF,         0x8CE0,       0x8CE7,
                              0x8CEF,        0x8CFF /* GL_COLOR_ATTACHMENT0, 7, 15, 31 */};
    for (GLenum b : buffers) {
        glDrawBuffer(b);
        w.error();
        w.get(GL_DRAW_BUFFER);
        glReadBuffer(b);
        w.error();
        w.get(GL_READ_BUFFER);
    }
    glBegin(GL_POINTS);
    glDrawBuffer(GL_FRONT);
    glReadBuffer(GL_FRONT);
    glEnd();
    w.error();
    // GL_COLOR_BUFFER_BIT keeps the draw buffer, GL_PIXEL_MODE_BIT the read buffer.
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
    glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
    glDrawBuffer(GL_FRONT);
    glReadBuffer(GL_FRONT);
    glPopAttrib();
    for (GLenum name : names) w.get(name);
    glNewList(1, GL_COMPILE);
    glDrawBuffer(GL_FRONT_LEFT);
    glReadBuffer(GL_FRONT_LEFT);
    glDrawBuffer(GL_AUX0);
    glEndList();
    w.error();
    for (GLenum name : names) w.get(name);
    glCallList(1);
    w.error();
    for (GLenum name : names) w.get(name);
    return w.out;
}

TEST(DrawReadBuffer, ValuesAndErrorsMatchTheReference) {
    const auto walks = onBothBackends<std::vector<double>>(bufferWalk);
    EXPECT_EQ(testing_support::firstDifference(walks.mygl, walks.osmesa), "");
}

// Front, back and left all draw into the one buffer; GL_NONE clears and draws no colour (depth
// is still written).
TEST(DrawReadBuffer, ClearsAndDrawsFollowTheDrawBufferAsTheReference) {
    const auto frames = onBothBackends<Frame>([] {
        glClearColor(0.2f, 0.4f, 0.6f, 1);
        glDrawBuffer(GL_BACK);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDrawBuffer(GL_NONE);
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glColor3f(0, 1, 0);
        glRectf(-0.5f, -0.5f, 0.5f, 0.5f);  // depth only
        glDrawBuffer(GL_FRONT);
        glColor3f(1, 1, 0);
        glBegin(GL_TRIANGLES);  // hidden where the rectangle wrote its depth
        glVertex3f(-0.9f, -0.9f, 0.5f), glVertex3f(0.9f, -0.9f, 0.5f), glVertex3f(0.0f, 0.9f, 0.5f);
        glEnd();
        glDrawBuffer(GL_FRONT_AND_BACK);
        glReadBuffer(GL_BACK);
        return readFrame(16, 16);
    });
    EXPECT_EQ(frames.mygl, frames.osmesa);
}

}  // namespace
