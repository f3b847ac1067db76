// glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib: for each group, push it,
// change everything MyGL has, pop, then draw and query; compared with OSMesa doing the same.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <vector>

#include "backends.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kSize = 16;

// Capabilities MyGL accepts but does not render yet (the queries compare them). Not GL_LIGHTi:
// OSMesa's pop of GL_ENABLE_BIT alone leaves a light enabled after the push as it is (the spec
// restores it; GL_LIGHTING_BIT does restore it there too).
constexpr GLenum kNotRendered[] = {GL_ALPHA_TEST,   GL_BLEND,     GL_FOG,          GL_LIGHTING,
                                   GL_LINE_SMOOTH,  GL_NORMALIZE, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH,
                                   GL_SCISSOR_TEST, GL_TEXTURE_2D};

// Every state value a group can hold that MyGL keeps, changed away from its default.
void changeEverything() {
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glNormal3f(0.0f, 1.0f, 0.0f);
    glTexCoord2f(0.1f, 0.2f);
    glEdgeFlag(GL_FALSE);
    glRasterPos3f(0.25f, -0.5f, 0.1f);
    for (GLenum cap : kNotRendered) glEnable(cap);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_DITHER);
    glClearColor(0.5f, 0.25f, 0.75f, 1.0f);
    glClearDepth(0.5);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glShadeModel(GL_FLAT);
    glLineWidth(3.0f);
    glPointSize(4.0f);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CW);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glMatrixMode(GL_PROJECTION);
    glViewport(2, 3, 9, 7);
    glDepthRange(0.75, 0.25);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glHint(GL_FOG_HINT, GL_FASTEST);
    glListBase(7);
}

// A smooth triangle, a wide line and a large point, drawn with the state as it is except for
// the capabilities MyGL does not render.
Frame drawScene() {
    for (GLenum cap : kNotRendered) glDisable(cap);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-0.9f, -0.8f, 0.2f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(0.85f, -0.6f, -0.4f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-0.2f, 0.9f, 0.6f);
    glEnd();
    glBegin(GL_LINES);
    glVertex3f(-0.8f, 0.7f, 0.0f);
    glVertex3f(0.7f, 0.1f, 0.0f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex3f(0.5f, 0.5f, -0.5f);
    glEnd();
    return readFrame(kSize, kSize);
}

// The answers of every query the groups touch.
std::vector<double> queryEverything() {
    std::vector<double> out;
    for (GLenum name : {GL_CURRENT_COLOR,
                        GL_CURRENT_NORMAL,
                        GL_CURRENT_TEXTURE_COORDS,
                        GL_EDGE_FLAG,
                        GL_CURRENT_RASTER_POSITION,
                        GL_CURRENT_RASTER_COLOR,
                        GL_CURRENT_RASTER_POSITION_VALID,
                        GL_COLOR_CLEAR_VALUE,
                        GL_DEPTH_CLEAR_VALUE,
                        GL_DEPTH_FUNC,
                        GL_DEPTH_WRITEMASK,
                        GL_SHADE_MODEL,
                        GL_LINE_WIDTH,
                        GL_POINT_SIZE,
                        GL_CULL_FACE_MODE,
                        GL_FRONT_FACE,
                        GL_POLYGON_MODE,
                        GL_MATRIX_MODE,
                        GL_VIEWPORT,
                        GL_DEPTH_RANGE,
                        GL_PERSPECTIVE_CORRECTION_HINT,
                        GL_FOG_HINT,
                        GL_LIST_BASE,
                        GL_ATTRIB_STACK_DEPTH,
                        GL_CLIENT_ATTRIB_STACK_DEPTH,
                        GL_PACK_ALIGNMENT,
                        GL_UNPACK_ALIGNMENT}) {
        GLdouble values[4] = {-9, -9, -9, -9};
        glGetDoublev(name, values);
        out.insert(out.end(), values, values + 4);
    }
    for (GLenum cap : kNotRendered) out.push_back(glIsEnabled(cap));
    for (GLenum cap : {GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_VERTEX_ARRAY, GL_COLOR_ARRAY})
        out.push_back(glIsEnabled(cap));
    out.push_back(glGetError());
    return out;
}

// Each answer compared on its own, so that a failure names the query.
void expectSameAnswers(const std::vector<double>& mygl, const std::vector<double>& osmesa, GLbitfield mask) {
    ASSERT_EQ(mygl.size(), osmesa.size());
    for (std::size_t i = 0; i < mygl.size(); ++i) {
        EXPECT_EQ(mygl[i], osmesa[i]) << "answer " << i << ", mask 0x" << std::hex << mask;
    }
}

struct Outcome {
    Frame frame;
    std::vector<double> queries;
    bool operator==(const Outcome&) const = default;
};

Outcome pushChangePop(GLbitfield mask) {
    glPushAttrib(mask);
    changeEverything();
    glPopAttrib();
    glFlush();
    // Drawn where the defaults would leave everything visible: a fresh modelview in any mode.
    Outcome outcome;
    outcome.queries = queryEverything();
    glMatrixMode(GL_MODELVIEW);
    outcome.frame = drawScene();
    return outcome;
}

}  // namespace

TEST(AttribStack, EachGroupRestoresWhatTheReferenceRestores) {
    const GLbitfield groups[] = {GL_CURRENT_BIT,
                                 GL_POINT_BIT,
                                 GL_LINE_BIT,
                                 GL_POLYGON_BIT,
                                 GL_POLYGON_STIPPLE_BIT,
                                 GL_PIXEL_MODE_BIT,
                                 GL_LIGHTING_BIT,
                                 GL_FOG_BIT,
                                 GL_DEPTH_BUFFER_BIT,
                                 GL_ACCUM_BUFFER_BIT,
                                 GL_STENCIL_BUFFER_BIT,
                                 GL_VIEWPORT_BIT,
                                 GL_TRANSFORM_BIT,
                                 GL_ENABLE_BIT,
                                 GL_COLOR_BUFFER_BIT,
                                 GL_HINT_BIT,
                                 GL_EVAL_BIT,
                                 GL_LIST_BIT,
                                 GL_TEXTURE_BIT,
                                 GL_SCISSOR_BIT,
                                 GL_ALL_ATTRIB_BITS,
                                 0u};
    for (GLbitfield mask : groups) {
        const auto outcomes = onBothBackends<Outcome>([&] { return pushChangePop(mask); });
        expectSameAnswers(outcomes.mygl.queries, outcomes.osmesa.queries, mask);
        EXPECT_EQ(outcomes.mygl.frame.color, outcomes.osmesa.frame.color) << "mask 0x" << std::hex << mask;
        EXPECT_EQ(outcomes.mygl.frame.depth, outcomes.osmesa.frame.depth) << "mask 0x" << std::hex << mask;
    }
}

TEST(AttribStack, NestedPushesRestoreInOrder) {
    const auto outcomes = onBothBackends<Outcome>([] {
        glPushAttrib(GL_LINE_BIT | GL_ENABLE_BIT);
        glLineWidth(5.0f);
        glEnable(GL_DEPTH_TEST);
        glPushAttrib(GL_DEPTH_BUFFER_BIT);
        glDepthFunc(GL_ALWAYS);
        glDisable(GL_DEPTH_TEST);
        glPopAttrib();  // depth test on again, GL_LESS
        Outcome outcome;
        outcome.frame = drawScene();
        glPopAttrib();
        outcome.queries = queryEverything();
        return outcome;
    });
    expectSameAnswers(outcomes.mygl.queries, outcomes.osmesa.queries, 0);
    EXPECT_EQ(outcomes.mygl.frame, outcomes.osmesa.frame);
}

TEST(AttribStack, DepthsOverflowAndUnderflowAsTheReference) {
    const auto answers = onBothBackends<std::vector<GLint>>([] {
        std::vector<GLint> out;
        for (GLenum name : {GL_MAX_ATTRIB_STACK_DEPTH, GL_MAX_CLIENT_ATTRIB_STACK_DEPTH}) {
            GLint value = -1;
            glGetIntegerv(name, &value);
            out.push_back(value);
        }
        glPopAttrib();
        out.push_back(static_cast<GLint>(glGetError()));
        glPopClientAttrib();
        out.push_back(static_cast<GLint>(glGetError()));
        for (int i = 0; i < 17; ++i) {
            glPushAttrib(GL_ALL_ATTRIB_BITS);
            glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
            out.push_back(static_cast<GLint>(glGetError()));
        }
        GLint depth = -1;
        glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &depth);
        out.push_back(depth);
        glGetIntegerv(GL_CLIENT_ATTRIB_STACK_DEPTH, &depth);
        out.push_back(depth);
        // Inside glBegin/glEnd.
        glBegin(GL_POINTS);
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glEnd();
        out.push_back(static_cast<GLint>(glGetError()));
        glBegin(GL_POINTS);
        glPopClientAttrib();
        glEnd();
        out.push_back(static_cast<GLint>(glGetError()));
        glGetIntegerv(GL_CLIENT_ATTRIB_STACK_DEPTH, &depth);
        out.push_back(depth);
        return out;
    });
    EXPECT_EQ(answers.mygl, answers.osmesa);
}

TEST(AttribStack, ClientGroupsRestorePixelStoreAndArrays) {
    const auto answers = onBothBackends<std::vector<double>>([] {
        static const GLfloat vertices[] = {0, 0, 1, 0, 0, 1};
        std::vector<double> out;
        for (GLbitfield mask : {GLbitfield{GL_CLIENT_PIXEL_STORE_BIT}, GLbitfield{GL_CLIENT_VERTEX_ARRAY_BIT},
                                GLbitfield{GL_CLIENT_ALL_ATTRIB_BITS}}) {
            glPushClientAttrib(mask);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
            glEnableClientState(GL_VERTEX_ARRAY);
            glVertexPointer(2, GL_FLOAT, 8, vertices);
            glDisableClientState(GL_COLOR_ARRAY);
            glPopClientAttrib();
            for (GLenum name : {GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT, GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_SIZE,
                                GL_VERTEX_ARRAY_STRIDE, GL_VERTEX_ARRAY_TYPE}) {
                GLdouble value = -1;
                glGetDoublev(name, &value);
                out.push_back(value);
            }
            GLvoid* pointer = nullptr;
            glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer);
            out.push_back(pointer == vertices ? 1.0 : 0.0);
            // Restore the defaults for the next group.
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glDisableClientState(GL_VERTEX_ARRAY);
        }
        out.push_back(glGetError());
        return out;
    });
    EXPECT_EQ(answers.mygl, answers.osmesa);
}

TEST(AttribStack, PushAndPopInDisplayListsRunWhenTheListRuns) {
    const auto outcomes = onBothBackends<Outcome>([] {
        const GLuint list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        // Not the current colour: OSMesa sets the current attributes a list leaves at its end,
        // after the list's own glPopAttrib (the spec: what the pop restored).
        glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT);
        glEnable(GL_DEPTH_TEST);
        glLineWidth(4.0f);
        glPopAttrib();
        glEndList();
        Outcome outcome;
        outcome.queries = queryEverything();  // compiling ran nothing
        glCallList(list);
        const std::vector<double> after = queryEverything();
        outcome.queries.insert(outcome.queries.end(), after.begin(), after.end());
        outcome.frame = drawScene();
        return outcome;
    });
    expectSameAnswers(outcomes.mygl.queries, outcomes.osmesa.queries, 0);
    EXPECT_EQ(outcomes.mygl.frame, outcomes.osmesa.frame);
}

TEST(AttribStack, OuterPopRestoresGroupsChangedInsideANestedPush) {
    // MyGL alone, as the spec says: OSMesa's pop of the inner push resets its record of the groups
    // changed since the outer push to what it was at the inner push, so its outer pop leaves the
    // polygon mode and line width as changed (Mesa 22.3's PopAttribState).
    mygl::Context context(kSize, kSize);
    context.makeCurrent();
    glPushAttrib(GL_POLYGON_BIT | GL_LINE_BIT);
    glPushAttrib(0);
    glPolygonMode(GL_FRONT, GL_POINT);
    glLineWidth(3.0f);
    glPopAttrib();
    glPopAttrib();
    GLint mode[2] = {0, 0};
    glGetIntegerv(GL_POLYGON_MODE, mode);
    GLfloat width = 0.0f;
    glGetFloatv(GL_LINE_WIDTH, &width);
    EXPECT_EQ(mode[0], GL_FILL);
    EXPECT_EQ(width, 1.0f);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
