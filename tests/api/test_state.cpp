// State queries, matrices and readback: the same calls on MyGL and OSMesa must agree, matrices
// to the bit (MyGL computes them with the reference's float arithmetic).
#include <gtest/gtest.h>

#include <mygl/glu.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

std::vector<GLfloat> modelviewAndProjection() {
    std::vector<GLfloat> m(32);
    glGetFloatv(GL_MODELVIEW_MATRIX, m.data());
    glGetFloatv(GL_PROJECTION_MATRIX, m.data() + 16);
    return m;
}

}  // namespace

TEST(Matrices, TransformSequencesEqualTheReferenceBitForBit) {
    const auto matrices = onBothBackends<std::vector<GLfloat>>([] {
        glMatrixMode(GL_PROJECTION);
        gluPerspective(53.0, 4.0 / 3.0, 0.7, 123.0);
        glFrustum(-0.3, 0.2, -0.25, 0.35, 0.5, 40.0);
        glOrtho(-2.0, 3.0, -1.5, 2.5, -1.0, 7.0);
        glMatrixMode(GL_MODELVIEW);
        gluLookAt(1.0, 2.0, 5.0, 0.1, -0.2, 0.3, 0.0, 1.0, 0.0);
        glTranslatef(0.3f, -1.7f, 2.9f);
        glRotatef(33.3f, 0.0f, 0.0f, 1.0f);
        glRotatef(-71.0f, 0.0f, 1.0f, 0.0f);
        glRotatef(12.5f, 1.0f, 0.0f, 0.0f);
        glRotated(47.0, 1.0, 2.0, -3.0);
        glScalef(1.5f, -0.75f, 2.25f);
        glPushMatrix();
        glTranslated(100.0, 0.0, 0.0);
        glPopMatrix();
        const GLdouble m[16] = {1, 0.5, 0, 0, 0.25, 1, 0, 0, 0, 0.125, 1, 0, 3, 2, 1, 1};
        glMultMatrixd(m);
        return modelviewAndProjection();
    });
    EXPECT_EQ(matrices.mygl, matrices.osmesa);
}

TEST(Matrices, AgreeWithGlm) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1.0f, 2.0f, 3.0f);
    glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    glScalef(2.0f, 3.0f, 4.0f);
    glm::mat4 expected = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
    expected = glm::rotate(expected, glm::radians(30.0f), glm::vec3(1, 1, 0));
    expected = glm::scale(expected, glm::vec3(2, 3, 4));
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], glm::value_ptr(expected)[i], 1e-5f) << i;

    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -0.75, 0.75, 1, 20);
    const glm::mat4 frustum = glm::frustum(-1.0f, 1.0f, -0.75f, 0.75f, 1.0f, 20.0f);
    glGetFloatv(GL_PROJECTION_MATRIX, m);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], glm::value_ptr(frustum)[i], 1e-5f) << i;
}

TEST(Matrices, StackDepthsMatchTheReference) {
    const auto depths = onBothBackends<std::vector<GLint>>([] {
        std::vector<GLint> v(4);
        glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &v[0]);
        glPushMatrix();
        glPushMatrix();
        glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &v[1]);
        glMatrixMode(GL_PROJECTION);
        glPushMatrix();
        glGetIntegerv(GL_PROJECTION_STACK_DEPTH, &v[2]);
        glGetIntegerv(GL_MATRIX_MODE, &v[3]);
        return v;
    });
    EXPECT_EQ(depths.mygl, (std::vector<GLint>{32, 3, 2, GL_PROJECTION}));
    EXPECT_EQ(depths.mygl, depths.osmesa);
}

// The vertex transform rounds each product and sums left to right, nothing fused. The depth of a
// line depends on the last bit of its ends' x, y, z and w (a0 = z - dz/dx * x), so outlines under
// a perspective show any difference: with fused multiply-adds a third of these triangles differ.
TEST(Matrices, VertexTransformGivesTheReferenceDepthsBitForBit) {
    const auto depths = onBothBackends<std::vector<GLuint>>(
        [] {
            glClear(GL_DEPTH_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glMatrixMode(GL_PROJECTION);
            glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 10.0);
            glMatrixMode(GL_MODELVIEW);
            glTranslatef(0.0f, 0.0f, -2.2f);
            glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
            glScalef(1.3f, 1.3f, 1.3f);
            glBegin(GL_TRIANGLES);
            for (int i = 0; i < 3 * 12; ++i) {
                const float t = static_cast<float>(i);
                glVertex3f(0.8f * std::sin(t * 1.7f), 0.7f * std::sin(t * 2.3f + 1.0f), 0.3f * std::sin(t * 0.9f));
            }
            glEnd();
            std::vector<GLuint> depth(64 * 48);
            glReadPixels(0, 0, 64, 48, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
            return depth;
        },
        64, 48);
    EXPECT_EQ(depths.mygl, depths.osmesa);
}

TEST(StateQueries, ConversionsBetweenTypesMatchTheReference) {
    const auto values = onBothBackends<std::vector<double>>([] {
        glClearColor(0.25f, 0.5f, 1.5f, -0.5f);  // clamped to [0, 1]
        glDepthRange(0.2, 0.7);
        glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
        glEnable(GL_CULL_FACE);
        std::vector<double> v;
        GLint i[4];
        GLfloat f[4];
        GLboolean b[4];
        glGetIntegerv(GL_COLOR_CLEAR_VALUE, i);
        v.insert(v.end(), i, i + 4);
        glGetFloatv(GL_COLOR_CLEAR_VALUE, f);
        v.insert(v.end(), f, f + 4);
        glGetDoublev(GL_DEPTH_RANGE, reinterpret_cast<GLdouble*>(&v.emplace_back()));
        glGetFloatv(GL_CURRENT_COLOR, f);
        v.insert(v.end(), f, f + 4);
        glGetBooleanv(GL_CULL_FACE, b);
        v.push_back(b[0]);
        glGetIntegerv(GL_DEPTH_BITS, i);
        v.push_back(i[0]);
        glGetIntegerv(GL_SUBPIXEL_BITS, i);
        v.push_back(i[0]);
        return v;
    });
    ASSERT_EQ(values.mygl.size(), values.osmesa.size());
    for (std::size_t i = 0; i < values.mygl.size(); ++i) EXPECT_EQ(values.mygl[i], values.osmesa[i]) << "value " << i;
}

TEST(ReadPixels, HonoursPackAlignmentAndTheWindowEdge) {
    const auto bytes = onBothBackends<std::vector<GLubyte>>([] {
        glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
        glClear(GL_COLOR_BUFFER_BIT);
        std::vector<GLubyte> out(64, 7);  // 3 pixels of RGB per row = 9 bytes, padded to 12
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(14, 14, 3, 3, GL_RGB, GL_UNSIGNED_BYTE, out.data());  // one column, one row outside
        return out;
    });
    EXPECT_EQ(bytes.mygl, bytes.osmesa);
    EXPECT_EQ(bytes.mygl[0], 51);  // round(0.2 * 255)
    EXPECT_EQ(bytes.mygl[6], 7);   // outside the window: untouched
}

// glClear honours glDepthMask: with depth writes off, the depth buffer keeps its values.
TEST(Clear, HonoursTheDepthWriteMask) {
    const auto depths = onBothBackends<std::vector<GLuint>>([] {
        glClearDepth(0.25);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDepthMask(GL_FALSE);
        glClearDepth(0.75);
        glClear(GL_DEPTH_BUFFER_BIT);
        std::vector<GLuint> out(16 * 16);
        glReadPixels(0, 0, 16, 16, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out.data());
        glDepthMask(GL_TRUE);
        glClear(GL_DEPTH_BUFFER_BIT);
        out.resize(out.size() + 1);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &out.back());
        return out;
    });
    EXPECT_EQ(depths.mygl, depths.osmesa);
    EXPECT_NE(depths.osmesa.front(), depths.osmesa.back());  // the masked clear was not done
}

TEST(BadInput, NonFiniteAndHugeCoordinatesDrawNothingWrongAndNeverCrash) {
    mygl::Context context(32, 32);
    context.makeCurrent();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    glClear(GL_COLOR_BUFFER_BIT);
    for (GLenum mode : {GL_TRIANGLES, GL_LINES, GL_POINTS, GL_QUADS}) {
        glBegin(mode);
        for (float v : {nan, inf, -inf, 1e30f, -1e30f, 1e-38f, 0.5f, 3e38f}) {
            glVertex4f(v, 0.5f, 0.0f, 1.0f);
            glVertex4f(0.5f, v, v, v);
            glVertex4f(-0.5f, -0.5f, 0.0f, v);
        }
        glEnd();
    }
    glMatrixMode(GL_MODELVIEW);
    glScalef(1e30f, 1e30f, 1e30f);
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glVertex2f(0, -1);
    glEnd();
    glViewport(-100000, -100000, 1 << 30, 1 << 30);
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glVertex2f(0, -1);
    glEnd();
    glFinish();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const auto& stats = context.stats();
    EXPECT_EQ(stats.triangles, stats.clippedAway + stats.culledBack + stats.culledFront + stats.culledZeroArea +
                                   stats.rasterized - stats.clipCreated);
}
