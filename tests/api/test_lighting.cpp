// Lighting: lit spheres per feature compared with OSMesa running the very same calls, and the
// lighting calls' state and errors likewise.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
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

void sphere(int slices = 24, int stacks = 16) {
    GLUquadric* q = gluNewQuadric();
    gluSphere(q, 1.0, slices, stacks);
    gluDeleteQuadric(q);
}

// A light at `position` with white diffuse and specular, and a reddish material.
void whiteLight(GLenum light, const GLfloat* position) {
    const GLfloat white[] = {1, 1, 1, 1}, dim[] = {0.1f, 0.1f, 0.1f, 1};
    glLightfv(light, GL_POSITION, position);
    glLightfv(light, GL_DIFFUSE, white);
    glLightfv(light, GL_SPECULAR, white);
    glLightfv(light, GL_AMBIENT, dim);
    glEnable(light);
}

void material(float shininess) {
    const GLfloat diffuse[] = {0.8f, 0.3f, 0.2f, 1}, specular[] = {0.7f, 0.7f, 0.7f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

// The scene: `setup` (lights, materials) in eye space, then a sphere turned and moved by the
// modelview, with the depth test on.
Frame litScene(const std::function<void()>& setup, const std::function<void()>& draw) {
    testing_support::clearedPerspectiveView(4.0f);
    glEnable(GL_LIGHTING);
    setup();
    glRotatef(30.0f, 0.3f, 1.0f, 0.2f);
    draw();
    return readFrame(kWidth, kHeight);
}

using Case = std::pair<std::string, std::function<void()>>;

void expectSameFrames(const std::vector<Case>& cases, const std::function<void()>& draw) {
    for (const auto& [name, setup] : cases) {
        const auto frames = onBothBackends<Frame>([&] { return litScene(setup, draw); }, kWidth, kHeight);
        const ColorDifference d = difference(frames.mygl, frames.osmesa);
        EXPECT_EQ(d.pixels, 0) << name << ": max channel difference " << d.maxChannel;
        EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << name;
    }
}

const GLfloat kDirectional[] = {0.5f, 0.8f, 1.0f, 0.0f};
const GLfloat kPositional[] = {1.5f, 1.0f, 2.0f, 1.0f};

}  // namespace

TEST(Lighting, DirectionalAndPositionalLightsMatchTheReference) {
    expectSameFrames(
        {
            {"directional, diffuse only",
             [] {
                 whiteLight(GL_LIGHT0, kDirectional);
                 material(0);
             }},
            {"default light 0", [] { glEnable(GL_LIGHT0); }},
            {"no light enabled", [] { material(10); }},
            {"positional",
             [] {
                 whiteLight(GL_LIGHT0, kPositional);
                 material(0);
             }},
            {"positional, attenuated",
             [] {
                 whiteLight(GL_LIGHT0, kPositional);
                 glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.5f);
                 glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
                 glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.05f);
                 material(0);
             }},
            {"emission and model ambient",
             [] {
                 const GLfloat emission[] = {0.1f, 0.2f, 0.05f, 1}, ambient[] = {0.3f, 0.2f, 0.4f, 1};
                 glMaterialfv(GL_FRONT, GL_EMISSION, emission);
                 glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
                 whiteLight(GL_LIGHT0, kDirectional);
             }},
        },
        [] { sphere(); });
}

// Specular weights are pow(n.H, shininess), which llvmpipe approximates (exp2 and log2
// polynomials): shininess 1 tells a true pow from the reference's.
TEST(Lighting, SpecularTermsMatchTheReference) {
    std::vector<Case> cases;
    for (float shininess : {0.0f, 1.0f, 5.0f, 10.0f, 50.0f, 128.0f}) {
        cases.emplace_back("directional, shininess " + std::to_string(shininess), [=] {
            whiteLight(GL_LIGHT0, kDirectional);
            material(shininess);
        });
        cases.emplace_back("positional, shininess " + std::to_string(shininess), [=] {
            whiteLight(GL_LIGHT0, kPositional);
            material(shininess);
        });
        cases.emplace_back("local viewer, shininess " + std::to_string(shininess), [=] {
            glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
            whiteLight(GL_LIGHT0, kDirectional);
            material(shininess);
        });
    }
    expectSameFrames(cases, [] { sphere(); });
}

TEST(Lighting, SpotLightsMatchTheReference) {
    std::vector<Case> cases;
    for (float exponent : {0.0f, 2.0f, 20.0f}) {
        cases.emplace_back("spot, exponent " + std::to_string(exponent), [=] {
            const GLfloat position[] = {0.0f, 0.5f, 3.0f, 1.0f}, direction[] = {0.0f, -0.2f, -1.0f};
            whiteLight(GL_LIGHT0, position);
            glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 25.0f);
            glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
            material(20);
        });
    }
    expectSameFrames(cases, [] { sphere(32, 24); });
}

TEST(Lighting, ColorMaterialNormalizeAndEightLightsMatchTheReference) {
    std::vector<Case> cases;
    for (GLenum mode : {GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE}) {
        cases.emplace_back("colour material " + std::to_string(mode), [=] {
            whiteLight(GL_LIGHT0, kDirectional);
            material(10);
            glColorMaterial(GL_FRONT, mode);
            glEnable(GL_COLOR_MATERIAL);
            glColor4f(0.2f, 0.6f, 0.9f, 0.5f);
        });
    }
    cases.emplace_back("scaled modelview, normalize", [] {
        whiteLight(GL_LIGHT0, kDirectional);
        material(10);
        glEnable(GL_NORMALIZE);
        glScalef(0.6f, 1.2f, 0.9f);
    });
    cases.emplace_back("scaled modelview, not normalized", [] {
        whiteLight(GL_LIGHT0, kDirectional);
        material(10);
        glScalef(0.6f, 1.2f, 0.9f);
    });
    cases.emplace_back("uniform scale, rescale normal", [] {
        whiteLight(GL_LIGHT0, kPositional);
        material(10);
        glEnable(GL_RESCALE_NORMAL);
        glScalef(0.7f, 0.7f, 0.7f);
    });
    cases.emplace_back("eight lights", [] {
        for (int i = 0; i < 8; ++i) {
            const float a = 0.8f * static_cast<float>(i);
            const GLfloat position[] = {std::cos(a), std::sin(a), 1.0f, i % 2 ? 1.0f : 0.0f};
            const GLfloat color[] = {0.3f + 0.08f * static_cast<float>(i), 0.2f, 0.5f - 0.05f * static_cast<float>(i),
                                     1};
            glLightfv(GL_LIGHT0 + static_cast<GLenum>(i), GL_POSITION, position);
            glLightfv(GL_LIGHT0 + static_cast<GLenum>(i), GL_DIFFUSE, color);
            glLightfv(GL_LIGHT0 + static_cast<GLenum>(i), GL_SPECULAR, color);
            glEnable(GL_LIGHT0 + static_cast<GLenum>(i));
        }
        material(30);
    });
    expectSameFrames(cases, [] { sphere(); });
}

// Colours per vertex with colour material, glMaterial between glBegin and glEnd, and flat
// shading (the provoking vertex's lit colour).
TEST(Lighting, PerVertexMaterialsAndFlatShadingMatchTheReference) {
    const auto strip = [] {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= 12; ++i) {
            const float a = -1.2f + 0.2f * static_cast<float>(i);
            const GLfloat diffuse[] = {0.1f * static_cast<float>(i % 7), 0.5f, 0.9f - 0.05f * static_cast<float>(i), 1};
            glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
            glColor3f(0.9f - 0.07f * static_cast<float>(i), 0.3f, 0.08f * static_cast<float>(i));
            glNormal3f(std::sin(a), 0.0f, std::cos(a));
            glVertex3f(1.5f * std::sin(a), -1.0f, 1.5f * std::cos(a) - 1.0f);
            glVertex3f(1.5f * std::sin(a), 1.0f, 1.5f * std::cos(a) - 1.0f);
        }
        glEnd();
    };
    expectSameFrames(
        {
            {"glMaterial inside glBegin/glEnd", [] { whiteLight(GL_LIGHT0, kPositional); }},
            {"colour material per vertex",
             [] {
                 whiteLight(GL_LIGHT0, kPositional);
                 glEnable(GL_COLOR_MATERIAL);
             }},
            {"flat",
             [] {
                 whiteLight(GL_LIGHT0, kPositional);
                 material(20);
                 glShadeModel(GL_FLAT);
             }},
        },
        strip);
}

// glMaterial after some vertices of a primitive, in a batch that merged earlier blocks: the
// vertices before it keep the old material, the ones after take the new one, and the blocks
// after glEnd light with the material as it was left.
TEST(Lighting, MaterialChangedAfterVerticesMatchesTheReference) {
    const auto triangles = [](float y, int count) {
        for (int i = 0; i < count; ++i) {
            const float x = -1.2f + 0.25f * static_cast<float>(i);
            glNormal3f(0.2f * static_cast<float>(i) - 0.5f, 0.3f, 1.0f);
            glVertex3f(x, y, -1.0f);
            glVertex3f(x + 0.2f, y, -1.0f);
            glVertex3f(x + 0.1f, y + 0.4f, -1.2f);
        }
    };
    const auto draw = [&] {
        const GLfloat red[] = {0.9f, 0.1f, 0.1f, 1}, blue[] = {0.1f, 0.2f, 0.9f, 1};
        glBegin(GL_TRIANGLES);
        triangles(-1.0f, 9);
        glEnd();
        glBegin(GL_TRIANGLES);
        triangles(-0.5f, 4);
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
        triangles(0.0f, 5);
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, blue);
        triangles(0.5f, 3);
        glEnd();
        glBegin(GL_TRIANGLES);
        triangles(0.9f, 9);
        glEnd();
    };
    expectSameFrames({{"one-sided", [] { whiteLight(GL_LIGHT0, kPositional); }},
                      {"two-sided",
                       [] {
                           whiteLight(GL_LIGHT0, kPositional);
                           glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                       }}},
                     draw);
}

// glMaterial inside primitives long enough to fill the reference's vertex buffer (a wrap that
// carries vertices over), with back faces, separate specular colours and a glColor midway: the
// vertices lit on the program's thread keep their back and secondary colours wherever they go.
TEST(Lighting, MaterialInsideLongPrimitivesMatchesTheReference) {
    constexpr int kVertices = 30000, kPasses = 8;
    const auto point = [](int i) {
        const float t = static_cast<float>(i / 2) / static_cast<float>(kVertices / 2) * kPasses;
        const int pass = static_cast<int>(t);
        const float u = t - static_cast<float>(pass), across = pass % 2 == 0 ? u : 1.0f - u;  // odd passes face back
        glNormal3f(across - 0.5f, 0.4f * static_cast<float>(i % 2) - 0.2f, 1.0f);
        glVertex3f(-1.4f + 2.8f * across, -1.2f + 0.3f * static_cast<float>(pass) + 0.25f * static_cast<float>(i % 2),
                   -1.0f + 0.1f * u);
    };
    const auto draw = [&](GLenum mode) {
        const GLfloat red[] = {0.9f, 0.1f, 0.1f, 1}, blue[] = {0.1f, 0.2f, 0.9f, 1};
        glBegin(mode);
        for (int i = 0; i < kVertices; ++i) {
            if (i == 1001) glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
            if (i == 12003) glColor3f(0.2f, 0.9f, 0.3f);
            if (i == 24005) glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, blue);
            point(i);
        }
        glEnd();
    };
    const Case twoSidedSeparate{"two-sided, separate specular", [] {
                                    whiteLight(GL_LIGHT0, kPositional);
                                    material(20.0f);
                                    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                                    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
                                }};
    const Case colorMaterial{"two-sided, colour material", [] {
                                 whiteLight(GL_LIGHT0, kDirectional);
                                 glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                                 glEnable(GL_COLOR_MATERIAL);
                             }};
    expectSameFrames({twoSidedSeparate, colorMaterial}, [&] { draw(GL_TRIANGLE_STRIP); });
    expectSameFrames({twoSidedSeparate}, [&] { draw(GL_QUAD_STRIP); });
    expectSameFrames({twoSidedSeparate}, [&] { draw(GL_LINE_LOOP); });
}

// The lighting calls' errors and the state they leave, as glGet and glGetLight/glGetMaterial
// report them.
TEST(Lighting, StateAndErrorsMatchTheReference) {
    const auto answers = onBothBackends<std::vector<double>>([] {
        std::vector<double> out;
        const auto error = [&] { out.push_back(static_cast<double>(glGetError())); };
        const auto floats = [&](std::initializer_list<GLfloat> values) {
            out.insert(out.end(), values.begin(), values.end());
        };
        const GLfloat v[] = {0.25f, -0.5f, 2.0f, 0.75f};
        const GLint iv[] = {1 << 30, -(1 << 29), 7, 2147483647};
        glLightfv(GL_LIGHT0 + 8, GL_DIFFUSE, v), error();
        glLightfv(GL_LIGHT1, GL_SHININESS, v), error();
        glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 129.0f), error();
        glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 91.0f), error();
        glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f), error();
        glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, -1.0f), error();
        glLightf(GL_LIGHT1, GL_DIFFUSE, 0.5f), error();
        glMaterialf(GL_FRONT, GL_SHININESS, 129.0f), error();
        glMaterialf(GL_LEFT, GL_SHININESS, 1.0f), error();
        glMaterialf(GL_FRONT, GL_POSITION, 1.0f), error();
        glLightModelf(GL_LIGHT0, 0.0f), error();
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT), error();
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR), error();
        glColorMaterial(GL_FRONT, GL_POSITION), error();
        glColorMaterial(GL_LEFT, GL_DIFFUSE), error();
        glBegin(GL_TRIANGLES);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, v);
        glMaterialfv(GL_BACK, GL_SPECULAR, v);
        glEnd();
        error();

        glMatrixMode(GL_MODELVIEW);
        glRotatef(40.0f, 0.0f, 1.0f, 0.0f);
        glTranslatef(1.0f, 2.0f, 3.0f);
        glLightfv(GL_LIGHT2, GL_POSITION, v);
        glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, v);
        glLightiv(GL_LIGHT2, GL_AMBIENT, iv);
        glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 45);
        glMaterialiv(GL_FRONT_AND_BACK, GL_EMISSION, iv);
        glMateriali(GL_BACK, GL_SHININESS, 17);
        glMaterialf(GL_FRONT, GL_SHININESS, 60.5f);  // glGetMaterialiv rounds it, glGetLightiv truncates
        glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 60.7f);
        glLightModeliv(GL_LIGHT_MODEL_AMBIENT, iv);
        glColorMaterial(GL_BACK, GL_SPECULAR);
        glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
        glEnable(GL_COLOR_MATERIAL);
        glColor4f(0.3f, 0.2f, 0.1f, 0.9f);
        error();
        for (GLenum name : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
                            GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION}) {
            GLfloat f[4] = {-9, -9, -9, -9};
            GLint i[4] = {-9, -9, -9, -9};
            glGetLightfv(GL_LIGHT2, name, f);
            glGetLightiv(GL_LIGHT2, name, i);
            floats({f[0], f[1], f[2], f[3]});
            out.insert(out.end(), {double(i[0]), double(i[1]), double(i[2]), double(i[3])});
        }
        for (GLenum face : {GL_FRONT, GL_BACK}) {
            for (GLenum name : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS}) {
                GLfloat f[4] = {-9, -9, -9, -9};
                GLint i[4] = {-9, -9, -9, -9};
                glGetMaterialfv(face, name, f);
                glGetMaterialiv(face, name, i);
                floats({f[0], f[1], f[2], f[3]});
                out.insert(out.end(), {double(i[0]), double(i[1]), double(i[2]), double(i[3])});
            }
        }
        error();
        GLfloat f[4];
        glGetLightfv(GL_LIGHT0 + 9, GL_AMBIENT, f), error();
        glGetLightfv(GL_LIGHT0, GL_SHININESS, f), error();
        glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, f), error();
        glGetMaterialfv(GL_FRONT, GL_POSITION, f), error();
        for (GLenum name : std::initializer_list<GLenum>{
                 GL_LIGHTING, GL_LIGHT0, GL_LIGHT7, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_COLOR_MATERIAL, GL_MAX_LIGHTS,
                 GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE,
                 GL_LIGHT_MODEL_COLOR_CONTROL, GL_COLOR_MATERIAL_FACE, GL_COLOR_MATERIAL_PARAMETER, GL_SHADE_MODEL}) {
            GLfloat g[4] = {-9, -9, -9, -9};
            glGetFloatv(name, g);
            floats({g[0], g[1], g[2], g[3]});
            error();
        }
        glEnable(GL_LIGHTING), glEnable(GL_LIGHT7), glEnable(GL_NORMALIZE), glEnable(GL_RESCALE_NORMAL);
        for (GLenum cap : std::initializer_list<GLenum>{GL_LIGHTING, GL_LIGHT7, GL_NORMALIZE, GL_RESCALE_NORMAL,
                                                        GL_COLOR_MATERIAL}) {
            out.push_back(glIsEnabled(cap));
        }
        error();
        return out;
    });
    ASSERT_EQ(answers.mygl.size(), answers.osmesa.size());
    for (std::size_t i = 0; i < answers.mygl.size(); ++i)
        EXPECT_EQ(answers.mygl[i], answers.osmesa[i]) << "answer " << i;
}

// Modelviews whose inverse the reference computes by its general methods: a shear (the
// adjugate), a projective matrix (Gauss-Jordan), and a gluLookAt product it finds to be a
// rotation (object-space lighting).
TEST(Lighting, ModelviewsOfEveryKindMatchTheReference) {
    const auto lit = [](const GLfloat* position) {
        whiteLight(GL_LIGHT0, position);
        material(20);
    };
    std::vector<Case> cases;
    for (const GLfloat* position : {kDirectional, kPositional}) {
        const std::string light = position == kDirectional ? "directional" : "positional";
        cases.emplace_back("shear, " + light, [=] {
            lit(position);
            const GLfloat shear[16] = {1, 0.2f, 0, 0, 0.3f, 1, 0.1f, 0, 0, 0, 1, 0, 0, 0, 0, 1};
            glMultMatrixf(shear);
        });
        cases.emplace_back("projective, " + light, [=] {
            lit(position);
            const GLfloat projective[16] = {1, 0, 0, 0.02f, 0, 1, 0, 0.01f, 0, 0, 1, 0, 0, 0, 0, 1};
            glMultMatrixf(projective);
        });
        cases.emplace_back("look-at, " + light, [=] {
            lit(position);
            gluLookAt(0.3, 0.2, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
        });
        cases.emplace_back("uniform scale, " + light, [=] {  // eye space, normals not unit length
            lit(position);
            glScalef(0.8f, 0.8f, 0.8f);
        });
    }
    expectSameFrames(cases, [] { sphere(); });
}

// A lit scene from a display list (materials and lights compiled in it) and from vertex arrays
// with a normal array.
TEST(Lighting, ListsAndArraysMatchTheReference) {
    static std::vector<GLfloat> vertices, normals;
    if (vertices.empty()) {
        for (int i = 0; i <= 16; ++i) {
            const float a = 0.35f * static_cast<float>(i);
            for (float y : {-1.0f, 1.0f}) {
                normals.insert(normals.end(), {std::cos(a), 0.3f * y, std::sin(a)});
                vertices.insert(vertices.end(), {1.2f * std::cos(a), y, 1.2f * std::sin(a)});
            }
        }
    }
    expectSameFrames(
        {
            {"display list",
             [] {
                 glNewList(1, GL_COMPILE);
                 whiteLight(GL_LIGHT1, kPositional);
                 glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 40.0f);
                 glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.0f);
                 material(12);
                 glEndList();
                 glCallList(1);
             }},
            {"vertex arrays",
             [] {
                 whiteLight(GL_LIGHT0, kPositional);
                 material(25);
                 glEnableClientState(GL_VERTEX_ARRAY);
                 glEnableClientState(GL_NORMAL_ARRAY);
                 glVertexPointer(3, GL_FLOAT, 0, vertices.data());
                 glNormalPointer(GL_FLOAT, 0, normals.data());
             }},
        },
        [] {
            GLboolean arrays = GL_FALSE;
            glGetBooleanv(GL_VERTEX_ARRAY, &arrays);
            if (arrays)
                glDrawArrays(GL_QUAD_STRIP, 0, static_cast<GLsizei>(vertices.size() / 3));
            else
                sphere();
        });
}

// Two-sided lighting: triangles facing back (by the window-space determinant, after clipping)
// take the back material lit with the reversed normal.
TEST(Lighting, TwoSidedLightingMatchesTheReference) {
    const auto twoSided = [](float frontShininess, float backShininess) {
        whiteLight(GL_LIGHT0, kPositional);
        material(frontShininess);
        const GLfloat backDiffuse[] = {0.2f, 0.4f, 0.9f, 1}, backSpecular[] = {0.5f, 0.9f, 0.5f, 1};
        glMaterialfv(GL_BACK, GL_DIFFUSE, backDiffuse);
        glMaterialfv(GL_BACK, GL_SPECULAR, backSpecular);
        glMaterialf(GL_BACK, GL_SHININESS, backShininess);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    };
    // A ring seen from above, its outside and inside both in view; a part crosses the near plane.
    const auto ring = [] {
        glRotatef(50.0f, 1.0f, 0.0f, 0.0f);
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= 24; ++i) {
            const float a = 0.2618f * static_cast<float>(i);
            glNormal3f(std::cos(a), 0.0f, std::sin(a));
            glVertex3f(1.4f * std::cos(a), -0.6f, 1.4f * std::sin(a));
            glVertex3f(1.4f * std::cos(a), 0.6f, 1.4f * std::sin(a));
        }
        glEnd();
    };
    expectSameFrames(
        {
            {"two-sided", [=] { twoSided(20, 40); }},
            {"two-sided, front shininess 0", [=] { twoSided(0, 10); }},
            {"two-sided, flat, clockwise front",
             [=] {
                 twoSided(20, 5);
                 glShadeModel(GL_FLAT);
                 glFrontFace(GL_CW);
             }},
            {"two-sided, clipped by the near plane",
             [=] {
                 twoSided(20, 40);
                 glTranslatef(0.0f, 0.0f, 2.6f);
             }},
            {"two-sided, back faces culled",
             [=] {
                 twoSided(20, 40);
                 glEnable(GL_CULL_FACE);
             }},
        },
        ring);
}

// Lit quads (a cube with a normal per face, two faces open to show the inside), split as the
// reference splits them on each path: smooth, flat, and two-sided (the draw module's split).
TEST(Lighting, LitQuadsAreSplitAsTheReferenceSplitsThem) {
    const auto cube = [] {
        static const GLfloat corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
        static const int faces[4][4] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}};
        static const GLfloat normals[4][3] = {{0, 0, -1}, {0, -1, 0}, {0, 1, 0}, {1, 0, 0}};
        glRotatef(35.0f, 1.0f, 0.2f, 0.0f);
        glBegin(GL_QUADS);
        for (int f = 0; f < 4; ++f) {
            for (int v : faces[f]) {
                glNormal3f(normals[f][0] + 0.3f * corners[v][0], normals[f][1] + 0.3f * corners[v][1],
                           normals[f][2] + 0.3f * corners[v][2]);
                glVertex3fv(corners[v]);
            }
        }
        glEnd();
    };
    const auto lit = [] {
        whiteLight(GL_LIGHT0, kPositional);
        material(30);
        glEnable(GL_NORMALIZE);
    };
    expectSameFrames(
        {
            {"smooth", lit},
            {"flat",
             [=] {
                 lit();
                 glShadeModel(GL_FLAT);
             }},
            {"two-sided, smooth",
             [=] {
                 lit();
                 glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
             }},
            {"two-sided, flat",
             [=] {
                 lit();
                 glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                 glShadeModel(GL_FLAT);
             }},
        },
        cube);
}

// GL_SEPARATE_SPECULAR_COLOR: the specular terms go into a second colour, clamped per vertex
// and interpolated apart, added to the colour after the texture environment and before fog.
// A bright material and a bright light make both colours reach 1, so that a sum clamped per
// vertex and one clamped per fragment differ.
TEST(Lighting, SeparateSpecularColorMatchesTheReference) {
    const auto separate = [](float shininess) {
        const GLfloat bright[] = {0.9f, 0.8f, 0.7f, 1}, dimMaterial[] = {0.5f, 0.2f, 0.3f, 0.6f};
        whiteLight(GL_LIGHT0, kDirectional);
        whiteLight(GL_LIGHT1, kPositional);
        glLightfv(GL_LIGHT1, GL_SPECULAR, bright);
        material(shininess);
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dimMaterial);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    };
    // A 4x4 texture of strong and weak texels, for the environments.
    const auto checker = [] {
        static GLubyte texels[4 * 4 * 4];
        for (int i = 0; i < 16; ++i) {
            const GLubyte v = ((i + i / 4) % 2) ? 255 : 60;
            texels[4 * i] = v, texels[4 * i + 1] = static_cast<GLubyte>(v / 2), texels[4 * i + 2] = 200,
                       texels[4 * i + 3] = v;
        }
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glEnable(GL_TEXTURE_2D);
    };
    expectSameFrames(
        {
            {"shininess 10", [=] { separate(10); }},
            {"shininess 60", [=] { separate(60); }},
            {"shininess 0", [=] { separate(0); }},
            {"flat",
             [=] {
                 separate(20);
                 glShadeModel(GL_FLAT);
             }},
            {"single colour again",
             [=] {
                 separate(20);
                 glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
             }},
            {"spot, attenuated",
             [=] {
                 separate(30);
                 glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 35.0f);
                 glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.0f);
                 glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.1f);
             }},
            {"modulated texture",
             [=] {
                 separate(15);
                 checker();
             }},
            {"replaced texture",
             [=] {
                 separate(15);
                 checker();
                 glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
             }},
            {"decal texture",
             [=] {
                 separate(15);
                 checker();
                 glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
             }},
            {"blend texture",
             [=] {
                 separate(15);
                 checker();
                 const GLfloat envColor[] = {0.3f, 0.9f, 0.6f, 0.5f};
                 glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
                 glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
             }},
            {"added texture under fog",
             [=] {
                 separate(15);
                 checker();
                 glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
                 glEnable(GL_FOG);
                 glFogi(GL_FOG_MODE, GL_EXP);
                 glFogf(GL_FOG_DENSITY, 0.2f);
             }},
            {"added texture under fog, single colour",
             [=] {
                 separate(15);
                 glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
                 checker();
                 glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
                 glEnable(GL_FOG);
                 glFogi(GL_FOG_MODE, GL_EXP);
                 glFogf(GL_FOG_DENSITY, 0.2f);
             }},
            {"decal texture, flat",
             [=] {
                 separate(15);
                 checker();
                 glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
                 glShadeModel(GL_FLAT);
             }},
            {"fog",
             [=] {
                 separate(15);
                 const GLfloat fogColor[] = {0.2f, 0.6f, 0.3f, 1};
                 glEnable(GL_FOG);
                 glFogi(GL_FOG_MODE, GL_LINEAR);
                 glFogf(GL_FOG_START, 3.0f);
                 glFogf(GL_FOG_END, 5.5f);
                 glFogfv(GL_FOG_COLOR, fogColor);
             }},
            {"blended",
             [=] {
                 separate(15);
                 glEnable(GL_BLEND);
                 glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
             }},
            {"two-sided, clipped by the near plane",
             [=] {
                 separate(25);
                 const GLfloat backSpecular[] = {0.2f, 0.9f, 0.5f, 1};
                 glMaterialfv(GL_BACK, GL_SPECULAR, backSpecular);
                 glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                 glTranslatef(0.0f, 0.0f, 2.7f);
             }},
            {"lines",
             [=] {
                 separate(20);
                 glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
             }},
            {"points",
             [=] {
                 separate(20);
                 glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
                 glPointSize(3.0f);
             }},
            {"lines, flat",
             [=] {
                 separate(20);
                 glShadeModel(GL_FLAT);
                 glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
             }},
            {"material inside glBegin",
             [=] {
                 separate(20);
                 glBegin(GL_TRIANGLES);
                 glMaterialf(GL_FRONT, GL_SHININESS, 5.0f);
                 glNormal3f(0.0f, 0.0f, 1.0f);
                 glVertex3f(-1.5f, -1.2f, 1.2f), glVertex3f(1.5f, -1.2f, 1.2f), glVertex3f(0.0f, 1.4f, 1.2f);
                 glEnd();
             }},
        },
        [] {
            GLUquadric* q = gluNewQuadric();
            gluQuadricTexture(q, GL_TRUE);
            gluSphere(q, 1.0, 24, 16);
            gluDeleteQuadric(q);
        });
}

// A lit raster position under separate specular: the bitmap and the image drawn there are
// compared whole with the reference's.
TEST(Lighting, BitmapsAndImagesUnderSeparateSpecularMatchTheReference) {
    const auto frames = onBothBackends<Frame>(
        [] {
            glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glEnable(GL_LIGHTING);
            whiteLight(GL_LIGHT0, kDirectional);
            material(8);
            glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
            static const GLubyte bits[8 * 4] = {0xFF, 0x0F, 0xF0, 0xAA, 0x55, 0x3C, 0xC3, 0x81, 0xFF, 0x0F, 0xF0,
                                                0xAA, 0x55, 0x3C, 0xC3, 0x81, 0xFF, 0x0F, 0xF0, 0xAA, 0x55, 0x3C,
                                                0xC3, 0x81, 0xFF, 0x0F, 0xF0, 0xAA, 0x55, 0x3C, 0xC3, 0x81};
            glNormal3f(0.2f, 0.3f, 1.0f);
            glRasterPos2f(-0.5f, -0.5f);
            glBitmap(32, 8, 0.0f, 0.0f, 0.0f, 0.0f, bits);
            static GLubyte image[8 * 8 * 4];
            for (int i = 0; i < 64 * 4; ++i) image[i] = static_cast<GLubyte>(i * 7);
            glRasterPos2f(0.2f, 0.2f);
            glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, image);
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    const ColorDifference d = difference(frames.mygl, frames.osmesa);
    EXPECT_EQ(d.pixels, 0) << "max channel difference " << d.maxChannel;
}
