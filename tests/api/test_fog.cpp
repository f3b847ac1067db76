// Fog: generated scenes across fog modes, densities, ranges and projections, compared with
// OSMesa running the very same calls, and glFog's state, attribute group and errors likewise.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::ColorDifference;
using testing_support::difference;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 96, kHeight = 72;

struct FogSetting {
    GLenum mode;
    float density, start, end;
};

std::string describe(const FogSetting& f) {
    return std::to_string(f.mode) + " density " + std::to_string(f.density) + " range " + std::to_string(f.start) +
           ".." + std::to_string(f.end);
}

void applyFog(const FogSetting& f) {
    const GLfloat color[] = {0.6f, 0.65f, 0.7f, 1.0f};
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, static_cast<GLint>(f.mode));
    glFogf(GL_FOG_DENSITY, f.density);
    glFogf(GL_FOG_START, f.start);
    glFogf(GL_FOG_END, f.end);
    glFogfv(GL_FOG_COLOR, color);
}

// A row of smooth-coloured quads going away from the viewer, a sphere, lines and points.
void fogScene() {
    glBegin(GL_QUADS);
    for (int i = 0; i < 8; ++i) {
        const float z0 = -static_cast<float>(i) * 2.5f, z1 = z0 - 2.5f;
        glColor3f(0.9f, 0.2f + 0.1f * static_cast<float>(i % 3), 0.1f);
        glVertex3f(-2.0f, -1.0f, z0);
        glColor3f(0.2f, 0.8f, 0.3f);
        glVertex3f(2.0f, -1.0f, z0);
        glColor3f(0.1f, 0.3f, 0.9f);
        glVertex3f(2.0f, -1.0f, z1);
        glVertex3f(-2.0f, -1.0f, z1);
    }
    glEnd();
    glColor3f(1.0f, 0.9f, 0.2f);
    GLUquadric* q = gluNewQuadric();
    glPushMatrix();
    glTranslatef(0.8f, 0.0f, -6.0f);
    gluSphere(q, 1.0, 20, 14);
    glPopMatrix();
    gluDeleteQuadric(q);
    glBegin(GL_LINES);
    for (int i = 0; i < 10; ++i) {
        glColor3f(1.0f, 0.1f * static_cast<float>(i), 0.5f);
        glVertex3f(-2.5f + 0.3f * static_cast<float>(i), 1.5f, 0.5f);
        glColor3f(0.0f, 1.0f, 0.2f);
        glVertex3f(-2.0f + 0.3f * static_cast<float>(i), 0.5f, -18.0f);
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 12; ++i) glVertex3f(2.2f, 1.2f, -1.5f * static_cast<float>(i));
    glEnd();
}

// The scene seen through a frustum (perspective) or a box (orthographic), from just in front
// of the first quad, so that near-plane clipping cuts some of it.
Frame fogFrame(bool perspective, const std::function<void()>& setup) {
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (perspective)
        glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 40.0);
    else
        glOrtho(-4.0, 4.0, -3.0, 3.0, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.2f, -2.0f);
    glRotatef(8.0f, 0.0f, 1.0f, 0.0f);
    setup();
    fogScene();
    return readFrame(kWidth, kHeight);
}

void expectSameFrame(const std::string& name, bool perspective, const std::function<void()>& setup) {
    const auto frames = onBothBackends<Frame>([&] { return fogFrame(perspective, setup); }, kWidth, kHeight);
    const ColorDifference d = difference(frames.mygl, frames.osmesa);
    EXPECT_EQ(d.pixels, 0) << name << ": max channel difference " << d.maxChannel;
    EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << name;
}

}  // namespace

// Every mode over densities and ranges (a range inside the scene, one beyond it, start after
// end, start equal to end), in perspective and orthographic views.
TEST(Fog, GeneratedModesDensitiesAndRangesMatchTheReference) {
    std::vector<FogSetting> settings;
    for (float density : {0.0f, 0.05f, 0.13f, 0.35f, 1.0f}) {
        settings.push_back({GL_EXP, density, 0.0f, 1.0f});
        settings.push_back({GL_EXP2, density, 0.0f, 1.0f});
    }
    for (const auto& [start, end] : std::vector<std::pair<float, float>>{
             {0.0f, 1.0f}, {2.0f, 20.0f}, {5.0f, 9.5f}, {-3.0f, 60.0f}, {15.0f, 4.0f}, {6.0f, 6.0f}}) {
        settings.push_back({GL_LINEAR, 1.0f, start, end});
    }
    for (bool perspective : {true, false}) {
        for (const FogSetting& f : settings) {
            expectSameFrame(describe(f) + (perspective ? ", perspective" : ", orthographic"), perspective,
                            [&] { applyFog(f); });
        }
    }
}

TEST(Fog, FlatShadingAndWideLinesMatchTheReference) {
    for (GLenum mode : {GL_LINEAR, GL_EXP, GL_EXP2}) {
        expectSameFrame("flat " + std::to_string(mode), true, [=] {
            applyFog({mode, 0.12f, 1.0f, 16.0f});
            glShadeModel(GL_FLAT);
            glLineWidth(3.0f);
        });
    }
}

// With a positional light or a local viewer, the reference takes the fog coordinate from the
// eye position that lighting computed, not from its own dot product: the last bits differ.
TEST(Fog, LitScenesMatchTheReference) {
    const GLfloat positional[] = {1.0f, 2.0f, 1.0f, 1.0f}, directional[] = {0.3f, 1.0f, 0.5f, 0.0f};
    for (const GLfloat* position : {positional, directional}) {
        for (bool localViewer : {false, true}) {
            const std::string name =
                std::string(position[3] != 0.0f ? "positional" : "directional") + (localViewer ? ", local viewer" : "");
            expectSameFrame(name, true, [=] {
                applyFog({GL_LINEAR, 1.0f, 2.0f, 2.0001f + 14.0f});
                glEnable(GL_LIGHTING);
                glEnable(GL_LIGHT0);
                glEnable(GL_COLOR_MATERIAL);
                glLightfv(GL_LIGHT0, GL_POSITION, position);
                glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, localViewer ? GL_TRUE : GL_FALSE);
                glRotatef(23.0f, 1.0f, 0.3f, 0.1f);
            });
        }
    }
}

// The fog coordinate's last bits, magnified: a LINEAR range of 2/100000 around each point's
// eye distance (under a general modelview) turns one unit in the last place of the distance
// into several steps of the colour. Lit by a positional light (emission white), the reference
// takes the distance from lighting's eye position, summed in the other order.
TEST(Fog, FogCoordinateBitsMatchTheReference) {
    for (bool lit : {false, true}) {
        const auto frame = [lit] {
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT);
            glMatrixMode(GL_PROJECTION);
            glLoadIdentity();
            glOrtho(-3.0, 3.0, -3.0, 3.0, -100.0, 100.0);
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            glTranslatef(0.1f, 0.2f, -7.3f);
            glRotatef(37.0f, 0.4f, 0.8f, 0.3f);
            GLfloat m[16];
            glGetFloatv(GL_MODELVIEW_MATRIX, m);
            glEnable(GL_FOG);
            glFogi(GL_FOG_MODE, GL_LINEAR);
            if (lit) {
                const GLfloat position[] = {0.0f, 0.0f, 1.0f, 1.0f}, white[] = {1, 1, 1, 1};
                glEnable(GL_LIGHTING);
                glEnable(GL_LIGHT0);
                glLightfv(GL_LIGHT0, GL_POSITION, position);
                glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, white);
            }
            for (int i = 0; i < 300; ++i) {
                const float a = 0.137f * static_cast<float>(i);
                const float x = 2.0f * std::sin(a * 1.3f), y = 2.0f * std::cos(a * 0.7f), z = 0.5f * std::sin(a * 3.1f);
                const double eyeZ = double(m[2]) * x + double(m[6]) * y + double(m[10]) * z + double(m[14]);
                glFogf(GL_FOG_START, static_cast<float>(std::fabs(eyeZ) - 1e-5));
                glFogf(GL_FOG_END, static_cast<float>(std::fabs(eyeZ) + 1e-5));
                glBegin(GL_POINTS);
                glVertex3f(x, y, z);
                glEnd();
            }
            return readFrame(kWidth, kHeight);
        };
        const auto frames = onBothBackends<Frame>(frame, kWidth, kHeight);
        const ColorDifference d = difference(frames.mygl, frames.osmesa);
        EXPECT_EQ(d.pixels, 0) << (lit ? "lit" : "unlit") << ": max channel difference " << d.maxChannel;
    }
}

// glGetFloatv of every fog parameter, glIsEnabled and the errors, after the same calls.
TEST(Fog, StateQueriesAndErrorsMatchTheReference) {
    struct Answers {
        std::vector<float> values;
        std::vector<GLenum> errors;
        bool operator==(const Answers&) const = default;
    };
    const auto answers = onBothBackends<Answers>([] {
        Answers a;
        const auto read = [&] {
            for (GLenum name : {GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_INDEX, GL_FOG_HINT}) {
                GLfloat v = -1;
                glGetFloatv(name, &v);
                a.values.push_back(v);
            }
            GLfloat color[4] = {};
            glGetFloatv(GL_FOG_COLOR, color);
            a.values.insert(a.values.end(), color, color + 4);
            GLint integerColor[4] = {};
            glGetIntegerv(GL_FOG_COLOR, integerColor);
            for (GLint c : integerColor) a.values.push_back(static_cast<float>(c / 65536));
            a.values.push_back(glIsEnabled(GL_FOG));
            a.errors.push_back(glGetError());
        };
        read();
        const GLfloat color[] = {0.25f, 1.5f, -0.5f, 0.75f};
        const GLint intColor[] = {0x40000000, -0x40000000, 0x7fffffff, 0};
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_DENSITY, 0.4f);
        glFogf(GL_FOG_START, -2.0f);
        glFogi(GL_FOG_END, 9);
        glFogf(GL_FOG_INDEX, 3.0f);
        glFogfv(GL_FOG_COLOR, color);
        glHint(GL_FOG_HINT, GL_NICEST);
        read();
        glFogiv(GL_FOG_COLOR, intColor);
        glFogf(GL_FOG_MODE, static_cast<GLfloat>(GL_EXP2));
        read();
        glFogi(GL_FOG_MODE, GL_FLAT);  // not a fog mode
        a.errors.push_back(glGetError());
        glFogf(GL_FOG_DENSITY, -1.0f);
        a.errors.push_back(glGetError());
        glFogf(GL_FOG_DENSITY + 100, 1.0f);
        a.errors.push_back(glGetError());
        glPushAttrib(GL_FOG_BIT);
        glDisable(GL_FOG);
        glFogf(GL_FOG_START, 5.0f);
        glPopAttrib();
        read();
        glBegin(GL_POINTS);
        glFogf(GL_FOG_START, 1.0f);
        glEnd();
        a.errors.push_back(glGetError());
        return a;
    });
    EXPECT_EQ(answers.mygl.values, answers.osmesa.values);
    EXPECT_EQ(answers.mygl.errors, answers.osmesa.errors);
}

// Bitmaps are fogged as at distance 0, whatever the raster position's distance: the reference
// draws them as a quad without a fog coordinate.
TEST(Fog, BitmapsMatchTheReference) {
    const GLubyte bits[] = {0xF0, 0x3C, 0x0F, 0xFF, 0x81, 0x7E, 0x18, 0xA5};
    for (const FogSetting& f : {FogSetting{GL_LINEAR, 1.0f, 10.0f, 2.0f}, FogSetting{GL_LINEAR, 1.0f, -4.0f, 6.0f},
                                FogSetting{GL_EXP, 0.3f, 0.0f, 1.0f}, FogSetting{GL_EXP2, 0.3f, 0.0f, 1.0f}}) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                glClearColor(0, 0, 0, 0);
                glClear(GL_COLOR_BUFFER_BIT);
                applyFog(f);
                glMatrixMode(GL_PROJECTION);
                glLoadIdentity();
                glOrtho(-1.0, 1.0, -1.0, 1.0, -20.0, 20.0);
                glColor3f(0.9f, 0.3f, 0.1f);
                glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of one byte
                for (int i = 0; i < 6; ++i) {
                    glRasterPos3f(-0.8f + 0.3f * static_cast<float>(i), 0.1f * static_cast<float>(i),
                                  -3.0f * static_cast<float>(i));
                    glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, bits);
                }
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        const ColorDifference d = difference(frames.mygl, frames.osmesa);
        EXPECT_EQ(d.pixels, 0) << describe(f) << ": max channel difference " << d.maxChannel;
    }
}
