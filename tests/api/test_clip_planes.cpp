// User clip planes (glClipPlane): scenes cut by one to eight planes, under several modelviews and
// projections, in every polygon mode and with lines and points, compared with OSMesa running
// the very same calls; the planes' state and errors likewise.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <limits>
#include <mygl/glu.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 96, kHeight = 72;

void sphere() {
    GLUquadric* q = gluNewQuadric();
    gluSphere(q, 1.0, 20, 14);
    gluDeleteQuadric(q);
}

// Smooth-coloured triangles, lines and points around the origin, from a fixed seed.
void mixedPrimitives() {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> coordinate(-1.3f, 1.3f), unit(0.0f, 1.0f);
    const auto vertex = [&] {
        glColor3f(unit(random), unit(random), unit(random));
        glVertex3f(coordinate(random), coordinate(random), coordinate(random));
    };
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 60; ++i) vertex();
    glEnd();
    glBegin(GL_LINES);
    for (int i = 0; i < 40; ++i) vertex();
    glEnd();
    glBegin(GL_POINTS);
    for (int i = 0; i < 40; ++i) vertex();
    glEnd();
}

struct Case {
    std::string name;
    std::function<void()> planes;  // with the modelview of the eye
    std::function<void()> draw;
};

Frame clippedScene(const Case& c) {
    testing_support::clearedPerspectiveView(4.0f);
    c.planes();
    glRotatef(25.0f, 0.4f, 1.0f, 0.1f);
    c.draw();
    return readFrame(kWidth, kHeight);
}

void expectSameFrames(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
        const auto frames = onBothBackends<Frame>([&] { return clippedScene(c); }, kWidth, kHeight);
        const testing_support::ColorDifference d = testing_support::difference(frames.mygl, frames.osmesa);
        EXPECT_EQ(d.pixels, 0) << c.name << ": max channel difference " << d.maxChannel;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << c.name;
    }
}

void plane(GLenum which, double a, double b, double c, double d) {
    const GLdouble equation[] = {a, b, c, d};
    glClipPlane(which, equation);
    glEnable(which);
}

}  // namespace

TEST(ClipPlanes, PlanesCutFilledPrimitivesAsTheReferenceDoes) {
    expectSameFrames({
        {"one plane through the sphere", [] { plane(GL_CLIP_PLANE0, 1, 0.3, 0, 0.2); }, sphere},
        {"plane given under a turned modelview",
         [] {
             glPushMatrix();
             glRotatef(40.0f, 0.0f, 0.0f, 1.0f);
             glTranslatef(0.2f, -0.1f, 0.3f);
             plane(GL_CLIP_PLANE2, 0, 1, 0.5, -0.1);
             glPopMatrix();
         },
         sphere},
        {"eight planes",
         [] {
             plane(GL_CLIP_PLANE0, 1, 0, 0, 0.7);
             plane(GL_CLIP_PLANE1, -1, 0, 0, 0.75);
             plane(GL_CLIP_PLANE2, 0, 1, 0, 0.6);
             plane(GL_CLIP_PLANE3, 0, -1, 0.2, 0.65);
             plane(GL_CLIP_PLANE4, 0.3, 0.3, 1, 0.5);
             plane(GL_CLIP_PLANE5, 0.2, -0.4, -1, 0.8);
             plane(GL_CLIP_PLANE0 + 6, 0.7, 0.7, 0, 0.8);
             plane(GL_CLIP_PLANE0 + 7, -0.6, 0.6, 0.3, 0.85);
         },
         sphere},
        {"a plane that removes everything", [] { plane(GL_CLIP_PLANE1, 0, 0, 0, -1); }, sphere},
        {"disabled again",
         [] {
             plane(GL_CLIP_PLANE0, 1, 0, 0, 0);
             glDisable(GL_CLIP_PLANE0);
         },
         sphere},
        {"triangles, lines and points", [] { plane(GL_CLIP_PLANE3, 0.6, -1, 0.4, 0.1); }, mixedPrimitives},
        {"culling and flat shading",
         [] {
             plane(GL_CLIP_PLANE0, 1, 1, 0, 0.3);
             glEnable(GL_CULL_FACE);
             glShadeModel(GL_FLAT);
         },
         mixedPrimitives},
    });
}

TEST(ClipPlanes, PlanesCutUnfilledPolygonsAndFollowTheProjection) {
    expectSameFrames({
        {"line mode",
         [] {
             plane(GL_CLIP_PLANE0, 1, 0.3, 0, 0.2);
             glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
         },
         sphere},
        {"point mode",
         [] {
             plane(GL_CLIP_PLANE4, -0.5, 1, 0.2, 0.1);
             glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
         },
         sphere},
        {"projection changed after the plane",
         [] {
             plane(GL_CLIP_PLANE0, 1, 0.3, 0, 0.2);
             glMatrixMode(GL_PROJECTION);
             glLoadIdentity();
             glOrtho(-2.0, 2.5, -1.5, 1.8, 1.0, 8.0);
             glMatrixMode(GL_MODELVIEW);
         },
         sphere},
        {"plane in a display list, restored by glPopAttrib",
         [] {
             const GLuint list = glGenLists(1);
             glNewList(list, GL_COMPILE);
             plane(GL_CLIP_PLANE1, 0, -1, 0.3, 0.25);
             glEndList();
             glPushAttrib(GL_TRANSFORM_BIT);
             plane(GL_CLIP_PLANE1, 1, 0, 0, 0);
             glCallList(list);
             glPushAttrib(GL_ENABLE_BIT | GL_TRANSFORM_BIT);
             plane(GL_CLIP_PLANE1, -1, 0, 0, 0);
             glDisable(GL_CLIP_PLANE1);
             glPopAttrib();
         },
         sphere},
    });
}

TEST(ClipPlanes, StateAndErrorsMatchTheReference) {
    const auto answers = onBothBackends<std::vector<double>>([] {
        std::vector<double> out;
        const auto error = [&] { out.push_back(glGetError()); };
        GLint maxPlanes = 0;
        glGetIntegerv(GL_MAX_CLIP_PLANES, &maxPlanes);
        out.push_back(maxPlanes);
        glMatrixMode(GL_MODELVIEW);
        glTranslatef(1.0f, 2.0f, -3.0f);
        glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
        const GLdouble equation[] = {1.0, -2.0, 0.5, 0.25};
        glClipPlane(GL_CLIP_PLANE3, equation);
        GLdouble eye[4] = {};
        glGetClipPlane(GL_CLIP_PLANE3, eye);
        out.insert(out.end(), eye, eye + 4);
        out.push_back(glIsEnabled(GL_CLIP_PLANE3));
        glEnable(GL_CLIP_PLANE3);
        out.push_back(glIsEnabled(GL_CLIP_PLANE3));
        GLboolean enabled = GL_FALSE;
        glGetBooleanv(GL_CLIP_PLANE3, &enabled);
        out.push_back(enabled);
        error();
        glClipPlane(GL_CLIP_PLANE0 + 8, equation);
        error();
        glEnable(GL_CLIP_PLANE0 + 8);
        error();
        glGetClipPlane(GL_CLIP_PLANE0 - 1, eye);
        error();
        glBegin(GL_POINTS);
        glClipPlane(GL_CLIP_PLANE0, equation);
        glEnd();
        error();
        return out;
    });
    EXPECT_EQ(answers.mygl, answers.osmesa);
}

// A plane with a NaN (here given under a modelview holding an infinity, whose inverse is NaN)
// puts every vertex outside: nothing is drawn, whatever the primitive.
TEST(ClipPlanes, ANanPlaneDrawsNothing) {
    for (const GLenum mode : {GL_POINTS, GL_LINES, GL_TRIANGLES}) {
        const auto frames = onBothBackends<Frame>([&] {
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            const GLfloat infinite[16] = {1, 1, 0, 0, 1, 0, 1, 1, std::numeric_limits<float>::infinity(),
                                          0, 0, 0, 0, 1, 1, 0};
            glLoadMatrixf(infinite);
            const GLdouble plane[] = {0.0, 0.0, 0.0, 1.0};
            glClipPlane(GL_CLIP_PLANE3, plane);
            glEnable(GL_CLIP_PLANE3);
            glLoadIdentity();
            glPointSize(3);
            glBegin(mode);
            glVertex3d(-0.5, -0.5, 0), glVertex3d(0.5, -0.4, 0), glVertex3d(0.1, 0.6, 0);
            glEnd();
            return readFrame(16, 16);
        });
        EXPECT_EQ(frames.mygl, frames.osmesa) << "mode " << mode;
    }
}
