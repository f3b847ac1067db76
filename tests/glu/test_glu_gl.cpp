// GLU's GL calls: matrices against closed forms and against OSMesa's state after the same calls,
// projection round trips, strings, and quadrics, tessellated polygons and mipmaps drawn through
// the same calls on MyGL and on OSMesa, compared pixel by pixel.
#include <gtest/gtest.h>

#include <mygl/glu.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <reference/compare.h>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

std::vector<GLfloat> matrix(GLenum which) {
    std::vector<GLfloat> m(16);
    glGetFloatv(which, m.data());
    return m;
}

void expectNear(const std::vector<GLfloat>& actual, const float* expected, const char* what) {
    for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(actual[i], expected[i], 1e-6f * (1.0f + std::fabs(expected[i]))) << what << " " << i;
}

TEST(GluMatrices, EqualTheirClosedForms) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    glMatrixMode(GL_PROJECTION);
    gluPerspective(50.0, 1.6, 0.5, 80.0);
    expectNear(matrix(GL_PROJECTION_MATRIX), glm::value_ptr(glm::perspective(glm::radians(50.0f), 1.6f, 0.5f, 80.0f)),
               "perspective");
    glLoadIdentity();
    gluOrtho2D(-3.0, 5.0, 1.0, 2.0);
    expectNear(matrix(GL_PROJECTION_MATRIX), glm::value_ptr(glm::ortho(-3.0f, 5.0f, 1.0f, 2.0f, -1.0f, 1.0f)),
               "ortho2D");
    glLoadIdentity();
    GLint viewport[4] = {10, 20, 200, 100};
    gluPickMatrix(60.0, 45.0, 4.0, 5.0, viewport);
    // The pick region (58..62, 42.5..47.5) must map onto the clip square [-1, 1].
    glm::mat4 pick = glm::translate(glm::mat4(1.0f),
                                    glm::vec3((200.0f - 2.0f * 50.0f) / 4.0f, (100.0f - 2.0f * 25.0f) / 5.0f, 0.0f));
    pick = glm::scale(pick, glm::vec3(200.0f / 4.0f, 100.0f / 5.0f, 1.0f));
    expectNear(matrix(GL_PROJECTION_MATRIX), glm::value_ptr(pick), "pick");
    const glm::vec4 corner =
        pick * glm::vec4(2.0f * (58.0f - 10.0f) / 200.0f - 1.0f, 2.0f * (42.5f - 20.0f) / 100.0f - 1.0f, 0, 1);
    EXPECT_NEAR(corner.x, -1.0f, 1e-5f);
    EXPECT_NEAR(corner.y, -1.0f, 1e-5f);
    gluPickMatrix(60.0, 45.0, 0.0, 5.0, viewport);  // an empty region leaves the matrix alone
    expectNear(matrix(GL_PROJECTION_MATRIX), glm::value_ptr(pick), "empty pick");
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(1.0, 2.0, 5.0, 0.1, -0.2, 0.3, 0.2, 1.0, 0.1);
    expectNear(
        matrix(GL_MODELVIEW_MATRIX),
        glm::value_ptr(glm::lookAt(glm::vec3(1, 2, 5), glm::vec3(0.1f, -0.2f, 0.3f), glm::vec3(0.2f, 1.0f, 0.1f))),
        "lookAt");
}

TEST(GluMatrices, LeaveTheSameStateOnBothBackends) {
    const auto state = onBothBackends<std::vector<GLfloat>>([] {
        glMatrixMode(GL_PROJECTION);
        GLint viewport[4] = {0, 0, 16, 16};
        gluPickMatrix(3.5, 9.25, 2.0, 3.0, viewport);
        gluPerspective(71.0, 0.8, 0.3, 45.0);
        glMatrixMode(GL_MODELVIEW);
        gluLookAt(-2.0, 1.0, 3.0, 0.5, 0.25, -1.0, 0.0, 0.0, 1.0);
        gluOrtho2D(-1.0, 2.0, -3.0, 4.0);
        std::vector<GLfloat> both = matrix(GL_PROJECTION_MATRIX), modelview = matrix(GL_MODELVIEW_MATRIX);
        both.insert(both.end(), modelview.begin(), modelview.end());
        return both;
    });
    EXPECT_EQ(state.mygl, state.osmesa);
}

TEST(GluProject, UnProjectInvertsProject) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    const glm::dmat4 proj = glm::perspective(glm::radians(60.0), 1.25, 0.5, 30.0);
    const glm::dmat4 model = glm::lookAt(glm::dvec3(1, 2, 6), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
    const GLint view[4] = {5, 7, 320, 240};
    for (int k = 0; k < 200; ++k) {
        const double x = coordinate(random), y = coordinate(random), z = coordinate(random);
        GLdouble wx, wy, wz, ox, oy, oz, ow;
        ASSERT_EQ(gluProject(x, y, z, glm::value_ptr(model), glm::value_ptr(proj), view, &wx, &wy, &wz), GL_TRUE);
        const glm::dvec4 clip = proj * model * glm::dvec4(x, y, z, 1.0);
        EXPECT_NEAR(wx, view[0] + (clip.x / clip.w + 1) / 2 * view[2], 1e-9);
        EXPECT_NEAR(wz, (clip.z / clip.w + 1) / 2, 1e-12);
        ASSERT_EQ(gluUnProject(wx, wy, wz, glm::value_ptr(model), glm::value_ptr(proj), view, &ox, &oy, &oz), GL_TRUE);
        EXPECT_NEAR(ox, x, 1e-9);
        EXPECT_NEAR(oy, y, 1e-9);
        EXPECT_NEAR(oz, z, 1e-9);
        // With w = 1 and the default depth range, UnProject4 gives the homogeneous form of the same point.
        ASSERT_EQ(gluUnProject4(wx, wy, wz, 1.0, glm::value_ptr(model), glm::value_ptr(proj), view, 0.0, 1.0, &ox, &oy,
                                &oz, &ow),
                  GL_TRUE);
        EXPECT_NEAR(ox / ow, x, 1e-9);
        EXPECT_NEAR(oz / ow, z, 1e-9);
    }
}

TEST(GluProject, RejectsSingularMatricesAndMissingArguments) {
    const double zero[16] = {}, identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const GLint view[4] = {0, 0, 10, 10};
    GLdouble x, y, z;
    EXPECT_EQ(gluUnProject(1, 1, 0.5, zero, identity, view, &x, &y, &z), GL_FALSE);
    EXPECT_EQ(gluProject(1, 1, 1, zero, identity, view, &x, &y, &z), GL_FALSE);  // w = 0
    EXPECT_EQ(gluProject(1, 1, 1, identity, identity, nullptr, &x, &y, &z), GL_FALSE);
    EXPECT_EQ(gluUnProject(1, 1, 0.5, identity, identity, view, nullptr, &y, &z), GL_FALSE);
    ASSERT_EQ(gluProject(0, 0, 0, identity, identity, view, &x, &y, &z), GL_TRUE);
    EXPECT_EQ(x, 5.0);
    EXPECT_EQ(y, 5.0);
    EXPECT_EQ(z, 0.5);
}

std::string text(const GLubyte* s) { return s ? reinterpret_cast<const char*>(s) : "(null)"; }

TEST(GluStrings, ErrorsVersionAndExtensions) {
    EXPECT_EQ(text(gluErrorString(GL_INVALID_ENUM)), "invalid enumerant");
    EXPECT_EQ(text(gluErrorString(GL_OUT_OF_MEMORY)), "out of memory");
    EXPECT_EQ(text(gluErrorString(GLU_INVALID_VALUE)), "invalid value");
    for (GLenum e = GLU_TESS_ERROR1; e <= GLU_TESS_ERROR6; ++e) EXPECT_NE(gluErrorString(e), nullptr) << e;
    EXPECT_EQ(gluErrorString(12345), nullptr);
    EXPECT_EQ(text(gluGetString(GLU_VERSION)).substr(0, 3), "1.3");
    EXPECT_NE(gluGetString(GLU_EXTENSIONS), nullptr);
    EXPECT_EQ(gluGetString(GL_VERSION), nullptr);
    auto check = [](const char* name, const char* list) {
        return gluCheckExtension(reinterpret_cast<const GLubyte*>(name), reinterpret_cast<const GLubyte*>(list));
    };
    EXPECT_EQ(check("GL_EXT_a", "GL_EXT_ab  GL_EXT_a"), GL_TRUE);
    EXPECT_EQ(check("GL_EXT_a", "GL_EXT_ab GL_EXT_abc"), GL_FALSE);
    EXPECT_EQ(check("GL_EXT", "GL_EXT_a"), GL_FALSE);
    EXPECT_EQ(check("", "GL_EXT_a"), GL_FALSE);
    EXPECT_EQ(check("GL_EXT_a", nullptr), GL_FALSE);
}

}  // namespace
