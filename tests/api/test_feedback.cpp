// GL_FEEDBACK: the buffers MyGL and OSMesa write for the same calls, compared value by value
// (bit for bit), with glRenderMode's answers, the queries and the errors.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/context.h>
#include <mygl/glu.h>

#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

constexpr int kWidth = 40, kHeight = 30;

struct Result {
    std::vector<GLfloat> buffer;
    GLint count = 0;
    GLenum error = GL_NO_ERROR;
    bool operator==(const Result& o) const {
        return count == o.count && error == o.error && buffer.size() == o.buffer.size() &&
               std::memcmp(buffer.data(), o.buffer.data(), buffer.size() * sizeof(GLfloat)) == 0;
    }
};

std::string describe(const Result& r) {
    std::ostringstream text;
    text.precision(9);
    text << "count " << r.count << " error " << r.error << ":";
    for (std::size_t i = 0; i < r.buffer.size() && i < static_cast<std::size_t>(r.count < 0 ? 64 : r.count); ++i)
        text << ' ' << r.buffer[i];
    return text.str();
}

// A perspective view with the texture coordinate set (it is every vertex's in feedback: see
// writeFeedbackPrimitives), then `draw` in feedback mode.
Result feedback(GLenum type, const std::function<void()>& draw, int size = 600) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.75, 0.75, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -2);
    glTexCoord2f(0.25f, 0.5f);
    Result r;
    r.buffer.assign(static_cast<std::size_t>(size), -7.0f);
    glFeedbackBuffer(size, type, r.buffer.data());
    glRenderMode(GL_FEEDBACK);
    draw();
    r.count = glRenderMode(GL_RENDER);
    r.error = glGetError();
    return r;
}

void smoothTriangles() {
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1);
    glVertex3f(-1, -1, 0);
    glColor4f(0, 1, 0, 0.5f);
    glVertex3f(1, -1, 0.5f);
    glColor4f(0, 0, 1, 0.25f);
    glVertex3f(0, 1, -0.5f);
    glColor3f(0.3f, 0.6f, 0.9f);
    glVertex3f(-0.5f, 0.2f, 0.3f);
    glVertex3f(0.7f, 0.1f, -0.2f);
    glVertex3f(0.2f, 0.6f, 0.1f);
    glEnd();
}

struct Case {
    const char* name;
    std::function<void()> draw;
};

std::vector<Case> cases() {
    return {
        {"triangles", smoothTriangles},
        {"flat triangles",
         [] {
             glShadeModel(GL_FLAT);
             smoothTriangles();
         }},
        {"quads and a polygon",
         [] {
             glBegin(GL_QUADS);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(1, 1);
             glVertex2f(-1, 1);
             glVertex2f(-0.5f, -0.5f);
             glVertex2f(0.5f, -0.4f);
             glVertex2f(0.6f, 0.5f);
             glVertex2f(-0.4f, 0.6f);
             glEnd();
             glBegin(GL_POLYGON);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(1.2f, 0.3f);
             glVertex2f(0, 1);
             glVertex2f(-1, 0.5f);
             glEnd();
         }},
        {"strips and fans",
         [] {
             glBegin(GL_TRIANGLE_STRIP);
             for (int i = 0; i < 6; ++i) glVertex3f(-1.0f + 0.4f * float(i), i % 2 ? 0.5f : -0.5f, 0.1f * float(i));
             glEnd();
             glBegin(GL_TRIANGLE_FAN);
             glVertex2f(0, 0);
             for (int i = 0; i < 5; ++i) glVertex2f(0.8f * float(i % 3) - 0.8f, 0.3f * float(i) - 0.6f);
             glEnd();
             glBegin(GL_QUAD_STRIP);
             for (int i = 0; i < 6; ++i) glVertex2f(-1.0f + 0.4f * float(i / 2), i % 2 ? 0.9f : 0.6f);
             glEnd();
         }},
        {"clipped triangles",
         [] {
             glBegin(GL_TRIANGLES);
             glColor3f(1, 0, 0);
             glVertex2f(-3, -0.5f);
             glColor3f(0, 1, 0);
             glVertex2f(0.5f, -0.5f);
             glColor3f(0, 0, 1);
             glVertex2f(0, 3);
             glVertex3f(-0.5f, -0.5f, 1.5f);
             glVertex3f(0.5f, -0.5f, -9.0f);
             glVertex3f(0, 0.5f, 0.5f);
             glEnd();
         }},
        {"lines, strips and loops, clipped",
         [] {
             glBegin(GL_LINES);
             glColor3f(1, 0.5f, 0);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glColor3f(0, 0.5f, 1);
             glVertex2f(-3, 0.2f);
             glVertex2f(3, 0.4f);
             glEnd();
             glBegin(GL_LINE_STRIP);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(1, 1);
             glVertex2f(4, 2);
             glEnd();
             glBegin(GL_LINE_LOOP);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(1, 1);
             glEnd();
         }},
        {"points, some outside",
         [] {
             glPointSize(4);
             glBegin(GL_POINTS);
             glColor3f(1, 1, 0);
             glVertex2f(0.5f, 0.25f);
             glVertex2f(5, 0);
             glColor3f(0, 1, 1);
             glVertex3f(-0.5f, -0.25f, 0.7f);
             glVertex3f(0, 0, -20);
             glEnd();
         }},
        {"culling",
         [] {
             glEnable(GL_CULL_FACE);
             glBegin(GL_TRIANGLES);
             glVertex2f(-1, -1);
             glVertex2f(0, 1);
             glVertex2f(1, -1);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(0, 1);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(3, -1);  // no area
             glEnd();
             glCullFace(GL_FRONT);
             smoothTriangles();
         }},
        {"lighting and two-sided lighting",
         [] {
             glEnable(GL_LIGHTING);
             glEnable(GL_LIGHT0);
             smoothTriangles();
             glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
             glBegin(GL_TRIANGLES);
             glVertex2f(-1, -1);
             glVertex2f(0, 1);
             glVertex2f(1, -1);
             glEnd();
         }},
        {"point polygon mode",
         [] {
             glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
             glBegin(GL_TRIANGLES);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(0, 1);
             glEnd();
             glBegin(GL_QUADS);
             glVertex2f(-0.5f, -0.5f);
             glVertex2f(0.5f, -0.4f);
             glVertex2f(0.6f, 0.5f);
             glVertex2f(-0.4f, 0.6f);
             glEnd();
         }},
        {"line polygon mode, every decomposition",
         [] {
             glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
             smoothTriangles();
             glBegin(GL_QUADS);
             glVertex2f(-0.5f, -0.5f);
             glVertex2f(0.5f, -0.4f);
             glVertex2f(0.6f, 0.5f);
             glVertex2f(-0.4f, 0.6f);
             glEnd();
             glBegin(GL_POLYGON);
             glVertex2f(-1, -1);
             glVertex2f(1, -1);
             glVertex2f(1.2f, 0.3f);
             glVertex2f(0, 1);
             glVertex2f(-1, 0.5f);
             glEnd();
             glBegin(GL_TRIANGLE_STRIP);
             for (int i = 0; i < 5; ++i) glVertex3f(-1.0f + 0.4f * float(i), i % 2 ? 0.5f : -0.5f, 0.1f * float(i));
             glEnd();
             glBegin(GL_TRIANGLE_FAN);
             glVertex2f(0, 0);
             glVertex2f(0.5f, 0);
             glVertex2f(0.4f, 0.4f);
             glVertex2f(0, 0.5f);
             glEnd();
             glBegin(GL_QUAD_STRIP);
             for (int i = 0; i < 6; ++i) glVertex2f(-1.0f + 0.4f * float(i / 2), i % 2 ? 0.9f : 0.6f);
             glEnd();
         }},
        {"line polygon mode, clipped and culled, lines after",
         [] {
             glPolygonMode(GL_FRONT, GL_LINE);
             glPolygonMode(GL_BACK, GL_FILL);
             glBegin(GL_TRIANGLES);
             glColor3f(1, 0, 0);
             glVertex2f(-3, -0.5f);
             glColor3f(0, 1, 0);
             glVertex2f(0.5f, -0.5f);
             glColor3f(0, 0, 1);
             glVertex2f(0, 3);
             glVertex2f(-1, -1);
             glVertex2f(0, 1);
             glVertex2f(1, -1);  // back: filled
             glEnd();
             glBegin(GL_POLYGON);
             glVertex2f(-2, -2);
             glVertex2f(2, -2);
             glVertex2f(2, 2);
             glVertex2f(-2, 2);
             glEnd();
             glEnable(GL_CULL_FACE);
             glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
             glBegin(GL_TRIANGLES);
             glVertex2f(-1, -1);
             glVertex2f(0, 1);
             glVertex2f(1, -1);  // culled
             glEnd();
             glBegin(GL_LINES);
             glVertex2f(-1, -1);
             glVertex2f(1, 1);
             glEnd();
             glShadeModel(GL_FLAT);
             glBegin(GL_QUADS);
             glColor3f(1, 0, 0);
             glVertex2f(-0.5f, -0.5f);
             glColor3f(0, 1, 0);
             glVertex2f(0.5f, -0.4f);
             glColor3f(0, 0, 1);
             glVertex2f(0.6f, 0.5f);
             glColor3f(1, 1, 1);
             glVertex2f(-0.4f, 0.6f);
             glEnd();
             glPolygonMode(GL_BACK, GL_FILL);
             glDisable(GL_CULL_FACE);
             glBegin(GL_TRIANGLES);  // a back face filled, flat, beside the unfilled stage
             glColor3f(1, 0, 0);
             glVertex2f(-1, -1);
             glColor3f(0, 1, 0);
             glVertex2f(0, 1);
             glColor3f(0, 0, 1);
             glVertex2f(1, -1);
             glEnd();
             glPolygonMode(GL_FRONT, GL_POINT);
             glBegin(GL_TRIANGLES);  // flat points
             glColor3f(1, 0, 0);
             glVertex2f(-1, -1);
             glColor3f(0, 1, 0);
             glVertex2f(1, -1);
             glColor3f(0, 0, 1);
             glVertex2f(0, 1);
             glEnd();
         }},
        {"pass-through, bitmaps and a display list",
         [] {
             glPassThrough(42.5f);
             glColor3f(0.5f, 0.25f, 1);
             glRasterPos2f(0.25f, 0.5f);
             const GLubyte bits[2] = {0xFF, 0xFF};
             glBitmap(8, 2, 0, 0, 3, 1, bits);
             glBitmap(8, 2, 0, 0, 3, 1, bits);
             glRasterPos2f(5, 5);
             glBitmap(8, 2, 0, 0, 3, 1, bits);
             glNewList(1, GL_COMPILE);
             glPassThrough(-3);
             glBegin(GL_POINTS);
             glVertex2f(0, 0);
             glEnd();
             glEndList();
             glCallList(1);
             glPassThrough(7);
         }},
        {"a gluSphere",
         [] {
             GLUquadric* q = gluNewQuadric();
             gluSphere(q, 0.8, 6, 4);
             gluDeleteQuadric(q);
         }},
    };
}

TEST(Feedback, EveryTypeWritesTheReferencesValues) {
    for (const Case& c : cases()) {
        for (GLenum type : {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE}) {
            const auto results = onBothBackends<Result>([&] { return feedback(type, c.draw); }, kWidth, kHeight);
            EXPECT_TRUE(results.mygl == results.osmesa)
                << c.name << ", type " << type << "\n MyGL:   " << describe(results.mygl)
                << "\n OSMesa: " << describe(results.osmesa);
        }
    }
}

TEST(Feedback, OverflowFillsTheBufferAndAnswersMinusOne) {
    for (int size : {1, 10, 23, 24}) {
        const auto results =
            onBothBackends<Result>([&] { return feedback(GL_3D_COLOR, smoothTriangles, size); }, kWidth, kHeight);
        EXPECT_TRUE(results.mygl == results.osmesa)
            << size << "\n MyGL:   " << describe(results.mygl) << "\n OSMesa: " << describe(results.osmesa);
    }
}

// A departure from the reference (docs/reference-rules.md): with glEdgeFlag calls, its feedback
// of an unfilled polygon is empty; GL writes the edges whose flags are set, as MyGL does.
TEST(Feedback, EdgeFlagsHideOnlyTheirEdgesOfAnUnfilledPolygon) {
    mygl::Context context(kWidth, kHeight);
    context.makeCurrent();
    const Result r = feedback(GL_2D, [] {
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glBegin(GL_QUADS);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glEdgeFlag(GL_FALSE);
        glVertex2f(1, 1);  // its edge, to the next vertex, is hidden
        glEdgeFlag(GL_TRUE);
        glVertex2f(-1, 1);
        glEnd();
    });
    const std::vector<GLfloat> expected = {GL_LINE_RESET_TOKEN, 10, 25, 10, 5, GL_LINE_TOKEN, 10, 5, 30, 5,
                                           GL_LINE_TOKEN,       30, 5,  30, 25};
    ASSERT_EQ(r.count, static_cast<GLint>(expected.size()));
    EXPECT_EQ(std::vector<GLfloat>(r.buffer.begin(), r.buffer.begin() + r.count), expected);
}

// Errors and queries, each value or error in call order.
std::vector<double> feedbackStateWalk() {
    std::vector<double> out;
    const auto error = [&] { out.push_back(glGetError()); };
    const auto get = [&](GLenum name) {
        GLint i = -1;
        glGetIntegerv(name, &i);
        out.push_back(i);
        error();
    };
    GLfloat buffer[8];
    get(GL_FEEDBACK_BUFFER_SIZE);
    get(GL_FEEDBACK_BUFFER_TYPE);
    glFeedbackBuffer(-1, GL_2D, buffer);
    error();
    glFeedbackBuffer(8, GL_RGBA, buffer);
    error();
    glFeedbackBuffer(8, GL_3D, nullptr);
    error();
    get(GL_FEEDBACK_BUFFER_SIZE);
    glFeedbackBuffer(8, GL_3D_COLOR, buffer);
    error();
    get(GL_FEEDBACK_BUFFER_SIZE);
    get(GL_FEEDBACK_BUFFER_TYPE);
    void* pointer = nullptr;
    glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &pointer);
    out.push_back(pointer == buffer);
    error();
    glBegin(GL_POINTS);
    glFeedbackBuffer(8, GL_3D, buffer);
    glPassThrough(1);
    glEnd();
    error();
    out.push_back(glRenderMode(GL_FEEDBACK));
    error();
    glFeedbackBuffer(8, GL_3D, buffer);
    error();
    get(GL_RENDER_MODE);
    glPassThrough(1);
    out.push_back(glRenderMode(GL_SELECT));  // leaves feedback; no select buffer yet
    error();
    out.push_back(glRenderMode(GL_RENDER));
    error();
    glPassThrough(1);  // ignored outside feedback
    error();
    glFeedbackBuffer(0, GL_3D, buffer);
    error();
    out.push_back(glRenderMode(GL_FEEDBACK));
    error();
    get(GL_RENDER_MODE);
    out.push_back(glRenderMode(GL_RENDER));
    error();
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glFeedbackBuffer(4, GL_2D, buffer);
    glPopAttrib();
    get(GL_FEEDBACK_BUFFER_SIZE);
    return out;
}

TEST(Feedback, ErrorsAndQueriesMatchTheReference) {
    const auto walks = onBothBackends<std::vector<double>>(feedbackStateWalk);
    EXPECT_EQ(testing_support::firstDifference(walks.mygl, walks.osmesa), "");
}

}  // namespace
