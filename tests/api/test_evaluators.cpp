// Evaluators: Bezier curves and surfaces (orders 1 to 6, rational ones, colour and normal maps,
// GL_AUTO_NORMAL under lighting, meshes in every mode, single glEvalCoord and glEvalPoint calls,
// display lists) compared with OSMesa running the very same calls; their state and errors too.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 96, kHeight = 72;

struct Case {
    std::string name;
    std::function<void()> draw;
};

void expectSameFrames(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                testing_support::clearedPerspectiveView(4.0f);
                glRotatef(-35.0f, 1.0f, 0.2f, 0.0f);
                c.draw();
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        const testing_support::ColorDifference d = testing_support::difference(frames.mygl, frames.osmesa);
        EXPECT_EQ(d.pixels, 0) << c.name << ": max channel difference " << d.maxChannel;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << c.name;
    }
}

// A bumpy net of uorder x vorder control points over [-1.2, 1.2]^2, `dim` components each
// (the fourth a weight).
std::vector<GLfloat> net(int uorder, int vorder, int dim) {
    std::vector<GLfloat> points;
    for (int i = 0; i < uorder; ++i) {
        for (int j = 0; j < vorder; ++j) {
            const float x = -1.2f + 2.4f * static_cast<float>(i) / static_cast<float>(std::max(uorder - 1, 1));
            const float y = -1.2f + 2.4f * static_cast<float>(j) / static_cast<float>(std::max(vorder - 1, 1));
            const float w = dim == 4 ? 1.0f + 0.3f * static_cast<float>((i + 2 * j) % 3) : 1.0f;
            const float z = 0.7f * std::sin(1.7f * static_cast<float>(i) + 0.9f * static_cast<float>(j));
            const GLfloat point[] = {x * w, y * w, z * w, w};
            points.insert(points.end(), point, point + dim);
        }
    }
    return points;
}

void litSurface() {
    const GLfloat position[] = {1.0f, 1.5f, 2.0f, 0.0f}, diffuse[] = {0.8f, 0.6f, 0.3f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
}

// A surface of the given orders through glMap2f and glEvalMesh2.
void surface(int uorder, int vorder, int dim, GLenum mode, bool autoNormal) {
    const std::vector<GLfloat> points = net(uorder, vorder, dim);
    const GLenum target = dim == 4 ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3;
    glMap2f(target, 0.0f, 1.0f, vorder * dim, uorder, 0.0f, 1.0f, dim, vorder, points.data());
    glEnable(target);
    if (autoNormal) glEnable(GL_AUTO_NORMAL);
    litSurface();
    glMapGrid2f(12, 0.0f, 1.0f, 9, 0.0f, 1.0f);
    glEvalMesh2(mode, 0, 12, 0, 9);
}

}  // namespace

TEST(Evaluators, CurvesMatchTheReference) {
    static const GLfloat control[4][3] = {
        {-1.5f, -1.2f, 0.0f}, {-0.5f, 1.6f, 0.3f}, {0.6f, -1.4f, -0.2f}, {1.5f, 1.1f, 0.0f}};
    static const GLfloat colors[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0.2f, 0.3f, 1, 1}};
    expectSameFrames({
        {"glEvalCoord1f in a line strip",
         [] {
             glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &control[0][0]);
             glEnable(GL_MAP1_VERTEX_3);
             glBegin(GL_LINE_STRIP);
             for (int i = 0; i <= 30; ++i) glEvalCoord1f(static_cast<GLfloat>(i) / 30.0f);
             glEnd();
         }},
        {"glEvalMesh1 with a colour map and a shifted domain",
         [] {
             glMap1f(GL_MAP1_VERTEX_3, 2.0f, 5.0f, 3, 4, &control[0][0]);
             glMap1f(GL_MAP1_COLOR_4, 2.0f, 5.0f, 4, 3, &colors[0][0]);
             glEnable(GL_MAP1_VERTEX_3);
             glEnable(GL_MAP1_COLOR_4);
             glMapGrid1f(25, 2.0f, 5.0f);
             glEvalMesh1(GL_LINE, 0, 25);
             glPointSize(3.0f);
             glEvalMesh1(GL_POINT, 3, 20);
         }},
        {"glEvalPoint1 and a list",
         [] {
             glMap1d(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4,
                     std::vector<GLdouble>(&control[0][0], &control[0][0] + 12).data());
             glEnable(GL_MAP1_VERTEX_3);
             glMapGrid1d(17, 0.1, 0.9);
             const GLuint list = glGenLists(1);
             glNewList(list, GL_COMPILE);
             glBegin(GL_LINE_STRIP);
             for (int i = 0; i <= 17; ++i) glEvalPoint1(i);
             glEnd();
             glEndList();
             glColor3f(0.9f, 0.8f, 0.1f);
             glCallList(list);
         }},
    });
}

TEST(Evaluators, SurfacesMatchTheReference) {
    expectSameFrames({
        {"4x4, filled, GL_AUTO_NORMAL", [] { surface(4, 4, 3, GL_FILL, true); }},
        {"4x4, lines", [] { surface(4, 4, 3, GL_LINE, false); }},
        {"4x4, points", [] { surface(4, 4, 3, GL_POINT, false); }},
        {"3x5, filled, GL_AUTO_NORMAL", [] { surface(3, 5, 3, GL_FILL, true); }},
        {"6x3, filled, GL_AUTO_NORMAL", [] { surface(6, 3, 3, GL_FILL, true); }},
        {"2x5, filled, GL_AUTO_NORMAL", [] { surface(2, 5, 3, GL_FILL, true); }},
        {"5x2, filled, GL_AUTO_NORMAL", [] { surface(5, 2, 3, GL_FILL, true); }},
        {"2x2, filled, GL_AUTO_NORMAL", [] { surface(2, 2, 3, GL_FILL, true); }},
        {"rational 4x4, filled, GL_AUTO_NORMAL", [] { surface(4, 4, 4, GL_FILL, true); }},
        {"rational 3x5, Horner", [] { surface(3, 5, 4, GL_FILL, false); }},
        {"normal and colour maps, single coordinates",
         [] {
             const std::vector<GLfloat> points = net(4, 3, 3);
             static const GLfloat normals[2][2][3] = {{{0, 0, 1}, {0.3f, 0, 1}}, {{0, 0.4f, 1}, {-0.2f, 0.2f, 1}}};
             static const GLfloat colors[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0, 1}}};
             glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 9, 4, 0.0f, 1.0f, 3, 3, points.data());
             glMap2f(GL_MAP2_NORMAL, 0.0f, 1.0f, 6, 2, 0.0f, 1.0f, 3, 2, &normals[0][0][0]);
             glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 8, 2, 0.0f, 1.0f, 4, 2, &colors[0][0][0]);
             glEnable(GL_MAP2_VERTEX_3);
             glEnable(GL_MAP2_NORMAL);
             glEnable(GL_MAP2_COLOR_4);
             litSurface();
             glEnable(GL_COLOR_MATERIAL);
             glBegin(GL_TRIANGLE_STRIP);
             for (int i = 0; i <= 10; ++i) {
                 glEvalCoord2f(static_cast<GLfloat>(i) / 10.0f, 0.2f);
                 glEvalCoord2f(static_cast<GLfloat>(i) / 10.0f, 0.7f);
             }
             glEnd();
             glMapGrid2f(6, 0.0f, 1.0f, 4, 0.0f, 1.0f);
             glBegin(GL_POINTS);
             for (int i = 0; i <= 6; ++i) glEvalPoint2(i, i % 5);
             glEnd();
         }},
    });
}

TEST(Evaluators, StateAndErrorsMatchTheReference) {
    const auto answers = onBothBackends<std::vector<double>>([] {
        std::vector<double> out;
        const auto error = [&] { out.push_back(glGetError()); };
        static const GLfloat points[] = {0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
        glMap2f(GL_MAP2_VERTEX_3, -1.0f, 2.0f, 9, 2, 0.5f, 1.5f, 3, 3, points);
        GLfloat coefficients[18] = {};
        glGetMapfv(GL_MAP2_VERTEX_3, GL_COEFF, coefficients);
        out.insert(out.end(), coefficients, coefficients + 18);
        GLint order[2] = {};
        glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, order);
        out.insert(out.end(), order, order + 2);
        GLdouble domain[4] = {};
        glGetMapdv(GL_MAP2_VERTEX_3, GL_DOMAIN, domain);
        out.insert(out.end(), domain, domain + 4);
        glGetMapdv(GL_MAP1_COLOR_4, GL_COEFF, domain);
        out.insert(out.end(), domain, domain + 4);
        glMapGrid2f(7, 0.25f, 0.75f, 3, 1.0f, 0.0f);
        GLfloat grid[4] = {};
        glGetFloatv(GL_MAP2_GRID_DOMAIN, grid);
        out.insert(out.end(), grid, grid + 4);
        GLint segments[2] = {};
        glGetIntegerv(GL_MAP2_GRID_SEGMENTS, segments);
        out.insert(out.end(), segments, segments + 2);
        GLint maxOrder = 0;
        glGetIntegerv(GL_MAX_EVAL_ORDER, &maxOrder);
        out.push_back(maxOrder);
        out.push_back(glIsEnabled(GL_MAP2_VERTEX_3));
        glEnable(GL_MAP2_VERTEX_3);
        glEnable(GL_AUTO_NORMAL);
        out.push_back(glIsEnabled(GL_MAP2_VERTEX_3));
        glPushAttrib(GL_EVAL_BIT);
        glDisable(GL_MAP2_VERTEX_3);
        glMapGrid2f(2, 0.0f, 1.0f, 2, 0.0f, 1.0f);
        glPopAttrib();
        out.push_back(glIsEnabled(GL_MAP2_VERTEX_3));
        out.push_back(glIsEnabled(GL_AUTO_NORMAL));
        glGetIntegerv(GL_MAP2_GRID_SEGMENTS, segments);
        out.insert(out.end(), segments, segments + 2);
        error();
        glMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 2, points);
        error();
        glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 2, 2, points);
        error();
        glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 31, points);
        error();
        glMap1f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, points);
        error();
        glMapGrid1f(0, 0.0f, 1.0f);
        error();
        glEvalMesh1(GL_FILL, 0, 3);
        error();
        glEvalMesh2(GL_LINE_STRIP, 0, 3, 0, 3);
        error();
        glGetMapfv(GL_MAP1_VERTEX_3, GL_VERTEX_ARRAY, coefficients);
        error();
        glBegin(GL_POINTS);
        glMapGrid1f(2, 0.0f, 1.0f);
        glEnd();
        error();
        return out;
    });
    EXPECT_EQ(answers.mygl, answers.osmesa);
}
