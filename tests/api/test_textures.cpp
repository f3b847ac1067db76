// Textures: generated scenes across filters, wraps, environment modes and formats, compared
// with OSMesa running the very same calls; texture objects, images, parameters, queries and
// errors likewise.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/glu.h>

#include <cstdint>
#include <functional>
#include <set>
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
constexpr int kClampToEdge = 0x812F;

// A size x size image of `components` bytes per texel: a pattern of smooth ramps and sharp
// steps, so that filtering and wrapping show.
std::vector<GLubyte> pattern(int width, int height, int components) {
    std::vector<GLubyte> texels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const bool check = ((x / 2) + (y / 2)) % 2 == 0;
            const GLubyte bytes[4] = {
                static_cast<GLubyte>(check ? 230 : 20 + 9 * x), static_cast<GLubyte>(255 * y / std::max(height - 1, 1)),
                static_cast<GLubyte>((x * 37 + y * 91) % 256), static_cast<GLubyte>(check ? 255 : 60 + 11 * y)};
            texels.insert(texels.end(), bytes, bytes + components);
        }
    }
    return texels;
}

struct TextureCase {
    GLenum minFilter, magFilter, wrap, env;
    GLint internalFormat;
    GLenum format;
    int components;
    int width, height;
};

std::string describe(const TextureCase& c) {
    return "min " + std::to_string(c.minFilter) + " mag " + std::to_string(c.magFilter) + " wrap " +
           std::to_string(c.wrap) + " env " + std::to_string(c.env) + " internal " + std::to_string(c.internalFormat) +
           " format " + std::to_string(c.format) + " " + std::to_string(c.width) + "x" + std::to_string(c.height);
}

// A textured quad in perspective (coordinates beyond [0, 1] to show the wrap), smooth colours,
// with the depth test; a smaller one flat and magnified.
Frame drawTextured(const TextureCase& c) {
    testing_support::clearedPerspectiveView(0.0f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    const std::vector<GLubyte> texels = pattern(c.width, c.height, c.components);
    glTexImage2D(GL_TEXTURE_2D, 0, c.internalFormat, c.width, c.height, 0, c.format, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(c.minFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(c.magFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(c.wrap));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(c.wrap));
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(c.env));
    const GLfloat envColor[] = {0.2f, 0.7f, 0.4f, 0.6f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.8f, 0.6f, 0.9f);
    glTexCoord2f(-0.3f, -0.2f);
    glVertex3f(-2.5f, -1.2f, -3.0f);
    glColor4f(0.5f, 1.0f, 0.7f, 0.5f);
    glTexCoord2f(1.7f, -0.2f);
    glVertex3f(2.5f, -1.2f, -3.0f);
    glColor4f(0.9f, 0.9f, 1.0f, 1.0f);
    glTexCoord2f(1.7f, 1.4f);
    glVertex3f(2.0f, 1.5f, -12.0f);
    glColor4f(0.3f, 0.6f, 1.0f, 0.7f);
    glTexCoord2f(-0.3f, 1.4f);
    glVertex3f(-2.0f, 1.5f, -12.0f);
    glEnd();
    glColor3f(0.8f, 0.9f, 1.0f);
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0.1f, 0.1f);
    glVertex3f(-0.6f, -0.5f, -1.5f);
    glTexCoord2f(0.45f, 0.15f);
    glVertex3f(0.3f, -0.55f, -1.6f);
    glTexCoord2f(0.2f, 0.4f);
    glVertex3f(-0.3f, 0.4f, -1.7f);
    glEnd();
    glDeleteTextures(1, &name);
    return readFrame(kWidth, kHeight);
}

// The frames identical; with DUMP set, each differing pixel printed.
void expectIdenticalFrames(const std::string& what, const testing_support::BothResults<Frame>& frames) {
    const ColorDifference d = difference(frames.mygl, frames.osmesa);
    EXPECT_EQ(d.pixels, 0) << what << ": max channel difference " << d.maxChannel;
    if (getenv("DUMP") && d.pixels) {
        for (int p = 0; p < kWidth * kHeight; ++p) {
            bool differ = false;
            for (int k = 0; k < 4; ++k) differ |= frames.mygl.color[4 * p + k] != frames.osmesa.color[4 * p + k];
            if (!differ) continue;
            printf("  (%d,%d) mygl %d %d %d %d osmesa %d %d %d %d\n", p % kWidth, p / kWidth, frames.mygl.color[4 * p],
                   frames.mygl.color[4 * p + 1], frames.mygl.color[4 * p + 2], frames.mygl.color[4 * p + 3],
                   frames.osmesa.color[4 * p], frames.osmesa.color[4 * p + 1], frames.osmesa.color[4 * p + 2],
                   frames.osmesa.color[4 * p + 3]);
        }
    }
}

void expectIdentical(const TextureCase& c) {
    expectIdenticalFrames(describe(c), onBothBackends<Frame>([&] { return drawTextured(c); }, kWidth, kHeight));
}

TEST(Textures, NearestAndLinearMagnifiedAcrossWrapsAndEnvironments) {
    for (const GLenum filter : {GL_NEAREST, GL_LINEAR}) {
        for (const GLenum wrap : {GLenum{GL_REPEAT}, GLenum{kClampToEdge}, GLenum{GL_CLAMP}}) {
            for (const GLenum env : {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD}) {
                expectIdentical({filter, filter, wrap, env, GL_RGBA, GL_RGBA, 4, 8, 8});
            }
        }
    }
}

TEST(Textures, FormatsAcrossEnvironments) {
    struct Format {
        GLint internal;
        GLenum format;
        int components;
    };
    const Format formats[] = {{GL_RGB, GL_RGB, 3},
                              {GL_RGBA8, GL_RGBA, 4},
                              {GL_LUMINANCE, GL_LUMINANCE, 1},
                              {1, GL_LUMINANCE, 1},
                              {GL_ALPHA, GL_ALPHA, 1},
                              {GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, 2},
                              {GL_INTENSITY, GL_LUMINANCE, 1},
                              {3, GL_RGBA, 4},
                              {GL_RGB8, GL_RGB, 3}};
    for (const Format& f : formats) {
        for (const GLenum env : {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD}) {
            expectIdentical({GL_NEAREST, GL_NEAREST, GL_REPEAT, env, f.internal, f.format, f.components, 8, 8});
            expectIdentical({GL_LINEAR, GL_LINEAR, GL_REPEAT, env, f.internal, f.format, f.components, 4, 8});
        }
    }
}

TEST(Textures, NonPowerOfTwoSizes) {
    for (const GLenum filter : {GL_NEAREST, GL_LINEAR}) {
        for (const GLenum wrap : {GLenum{GL_REPEAT}, GLenum{kClampToEdge}}) {
            expectIdentical({filter, filter, wrap, GL_MODULATE, GL_RGBA, GL_RGBA, 4, 5, 7});
            expectIdentical({filter, filter, wrap, GL_REPLACE, GL_RGB, GL_RGB, 3, 12, 3});
        }
    }
}

// A long floor going away from the viewer (minified more and more) with a mipmapped texture,
// every level given, each level's pattern different so that the chosen level shows.
Frame drawMipmappedFloor(GLenum minFilter, GLenum magFilter, GLenum wrap, int size, float repeat) {
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    for (int level = 0, side = size; side >= 1; ++level, side /= 2) {
        std::vector<GLubyte> texels = pattern(side, side, 4);
        for (std::size_t i = 0; i < texels.size(); i += 4) texels[i + 2] = static_cast<GLubyte>(40 * level);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, side, side, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glEnable(GL_TEXTURE_2D);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-3.0f, -1.0f, -1.2f);
    glTexCoord2f(repeat, 0.0f);
    glVertex3f(3.0f, -1.0f, -1.2f);
    glTexCoord2f(repeat, repeat * 4.0f);
    glVertex3f(3.0f, -1.0f, -50.0f);
    glTexCoord2f(0.0f, repeat * 4.0f);
    glVertex3f(-3.0f, -1.0f, -50.0f);
    glEnd();
    glDeleteTextures(1, &name);
    return readFrame(kWidth, kHeight);
}

TEST(Textures, MipmappedFloorAcrossFilters) {
    const GLenum minFilters[] = {GL_NEAREST,
                                 GL_LINEAR,
                                 GL_NEAREST_MIPMAP_NEAREST,
                                 GL_LINEAR_MIPMAP_NEAREST,
                                 GL_NEAREST_MIPMAP_LINEAR,
                                 GL_LINEAR_MIPMAP_LINEAR};
    for (const GLenum minFilter : minFilters) {
        for (const GLenum magFilter : {GL_NEAREST, GL_LINEAR}) {
            for (const float repeat : {0.5f, 3.0f}) {
                const auto frames = onBothBackends<Frame>(
                    [&] { return drawMipmappedFloor(minFilter, magFilter, GL_REPEAT, 16, repeat); }, kWidth, kHeight);
                const ColorDifference d = difference(frames.mygl, frames.osmesa);
                // Each level has its own blue: minified mipmaps show several.
                std::set<GLubyte> blues;
                for (std::size_t p = 2; p < frames.osmesa.color.size(); p += 4) blues.insert(frames.osmesa.color[p]);
                if (minFilter != GL_NEAREST && minFilter != GL_LINEAR) {
                    EXPECT_GT(blues.size(), 4u);
                }
                EXPECT_EQ(d.pixels, 0) << "min " << minFilter << " mag " << magFilter << " repeat " << repeat
                                       << ": max channel difference " << d.maxChannel;
            }
        }
    }
}

// A scene under `setUp` (texture state), textured with a small 8 x 8 texture: a quad, a
// sphere (normals for SPHERE_MAP) and a lit torus-like strip, in perspective.
Frame drawWithTexturing(const std::function<void()>& setUp) {
    testing_support::clearedPerspectiveView(4.0f);
    glTranslatef(0.2f, -0.1f, 0.0f);
    glRotatef(25.0f, 1.0f, 0.4f, 0.0f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    const std::vector<GLubyte> texels = pattern(8, 8, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    setUp();
    // A constant colour other than 0 or 1: the reference takes it exactly, not interpolated.
    glColor3f(0.9f, 0.8f, 0.7f);
    glBegin(GL_QUADS);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-1.8f, -1.2f, -0.5f);
    glTexCoord2f(2.0f, 0.0f);
    glVertex3f(0.2f, -1.2f, -0.5f);
    glTexCoord2f(2.0f, 2.0f);
    glVertex3f(0.2f, 0.8f, -0.9f);
    glTexCoord2f(0.0f, 2.0f);
    glVertex3f(-1.8f, 0.8f, -0.9f);
    glEnd();
    GLUquadric* q = gluNewQuadric();
    gluQuadricTexture(q, GL_TRUE);
    glTranslatef(0.9f, 0.3f, 0.2f);
    gluSphere(q, 0.8, 16, 12);
    gluDeleteQuadric(q);
    glDeleteTextures(1, &name);
    return readFrame(kWidth, kHeight);
}

void expectIdenticalWith(const std::string& what, const std::function<void()>& setUp) {
    expectIdenticalFrames(what, onBothBackends<Frame>([&] { return drawWithTexturing(setUp); }, kWidth, kHeight));
}

TEST(Textures, TexGenModesPerCoordinate) {
    const GLfloat sPlane[] = {0.6f, 0.2f, 0.0f, 0.3f}, tPlane[] = {0.0f, 0.5f, 0.4f, -0.2f};
    for (const GLenum mode : {GL_OBJECT_LINEAR, GL_EYE_LINEAR}) {
        expectIdenticalWith("texgen " + std::to_string(mode), [&] {
            const GLenum planeName = mode == GL_OBJECT_LINEAR ? GL_OBJECT_PLANE : GL_EYE_PLANE;
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, static_cast<GLint>(mode));
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, static_cast<GLint>(mode));
            glTexGenfv(GL_S, planeName, sPlane);
            glTexGenfv(GL_T, planeName, tPlane);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
        });
    }
    expectIdenticalWith("texgen S only", [&] {
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
        glTexGenfv(GL_S, GL_OBJECT_PLANE, sPlane);
        glEnable(GL_TEXTURE_GEN_S);
    });
    expectIdenticalWith("sphere map", [&] {
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
    });
}

TEST(Textures, TextureMatrixAndProjectiveCoordinates) {
    expectIdenticalWith("texture matrix", [] {
        glMatrixMode(GL_TEXTURE);
        glTranslatef(0.25f, -0.1f, 0.0f);
        glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
        glScalef(1.5f, 0.75f, 1.0f);
        glMatrixMode(GL_MODELVIEW);
    });
    expectIdenticalWith("projective q", [] {
        glMatrixMode(GL_TEXTURE);
        const GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.3f, 0, 0, 0, 1.2f};
        glLoadMatrixf(m);
        glMatrixMode(GL_MODELVIEW);
    });
}

TEST(Textures, SubImagesCopiesAndOneDimensional) {
    expectIdenticalWith("sub-image", [] {
        const std::vector<GLubyte> patch = pattern(3, 2, 3);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 5, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, patch.data());
    });
    expectIdenticalWith("sub-image between draws", [] {
        glBegin(GL_TRIANGLES);
        glTexCoord2f(0.0f, 0.0f);
        glVertex3f(-0.5f, 0.6f, 0.5f);
        glTexCoord2f(1.0f, 0.0f);
        glVertex3f(0.5f, 0.6f, 0.5f);
        glTexCoord2f(0.5f, 1.0f);
        glVertex3f(0.0f, 1.2f, 0.5f);
        glEnd();
        const GLubyte red[4 * 8] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255,
                                    255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
    });
    expectIdenticalWith("copy tex image", [] {
        glClearColor(0.3f, 0.6f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 10, 10, 16, 8, 0);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 40, 30, 4, 4);
        glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    });
    expectIdenticalWith("1D", [] {
        glDisable(GL_TEXTURE_2D);
        const std::vector<GLubyte> line = pattern(16, 1, 4);
        glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, line.data());
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glEnable(GL_TEXTURE_1D);
    });
    expectIdenticalWith("1D mipmapped, minified", [] {
        glDisable(GL_TEXTURE_2D);
        for (int level = 0, side = 16; side >= 1; ++level, side /= 2) {
            std::vector<GLubyte> line = pattern(side, 1, 4);
            for (std::size_t i = 2; i < line.size(); i += 4) line[i] = static_cast<GLubyte>(50 * level);
            glTexImage1D(GL_TEXTURE_1D, level, GL_RGBA, side, 0, GL_RGBA, GL_UNSIGNED_BYTE, line.data());
        }
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glEnable(GL_TEXTURE_1D);
        glMatrixMode(GL_TEXTURE);
        glScalef(6.0f, 1.0f, 1.0f);
        glMatrixMode(GL_MODELVIEW);
    });
    expectIdenticalWith("unpack row length and skips, floats", [] {
        std::vector<GLfloat> image(12 * 10 * 4);
        for (std::size_t i = 0; i < image.size(); ++i) image[i] = static_cast<float>((i * 37) % 101) / 100.0f;
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, image.data());
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    });
}

TEST(Textures, DisplayListsAndAttributeStack) {
    expectIdenticalWith("texture calls in a list", [] {
        const std::vector<GLubyte> image = pattern(4, 4, 3);
        const GLuint list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, image.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glEndList();
        glCallList(list);
        glDeleteLists(list, 1);
    });
    expectIdenticalWith("pop attrib restores the environment", [] {
        glPushAttrib(GL_TEXTURE_BIT);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        glDisable(GL_TEXTURE_2D);
        glPopAttrib();
    });
}

// The same queries on both backends: every value equal.
std::vector<double> textureQueries() {
    std::vector<double> values;
    auto integers = [&](GLenum name, int count) {
        GLint v[16] = {};
        glGetIntegerv(name, v);
        values.insert(values.end(), v, v + count);
    };
    GLuint names[3] = {};
    glGenTextures(3, names);
    values.insert(values.end(), names, names + 3);
    values.push_back(glIsTexture(names[1]));
    glBindTexture(GL_TEXTURE_2D, names[1]);
    values.push_back(glIsTexture(names[1]));
    integers(GL_TEXTURE_BINDING_2D, 1);
    const std::vector<GLubyte> image = pattern(4, 2, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    for (const GLenum name :
         {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER, GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE,
          GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE}) {
        GLint v = -1;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, name, &v);
        values.push_back(v);
    }
    const GLfloat border[] = {0.25f, 0.5f, 2.0f, -1.0f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, 0x812F);
    for (const GLenum name : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
                              GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_PRIORITY}) {
        GLfloat v[4] = {-9, -9, -9, -9};
        glGetTexParameterfv(GL_TEXTURE_2D, name, v);
        values.insert(values.end(), v, v + 4);
    }
    GLubyte back[4 * 2 * 4] = {};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    values.insert(values.end(), back, back + sizeof back);
    const GLfloat envColor[] = {0.1f, 0.2f, 0.3f, 0.4f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    GLint env[4] = {};
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env);
    values.push_back(env[0]);
    GLfloat color[4] = {};
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color);
    values.insert(values.end(), color, color + 4);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1.0f, 2.0f, 3.0f);
    const GLdouble plane[] = {1.0, 2.0, 3.0, 4.0};
    glTexGendv(GL_T, GL_EYE_PLANE, plane);
    GLdouble eye[4] = {};
    glGetTexGendv(GL_T, GL_EYE_PLANE, eye);
    values.insert(values.end(), eye, eye + 4);
    glEnable(GL_TEXTURE_GEN_R);
    values.push_back(glIsEnabled(GL_TEXTURE_GEN_R));
    // GL_TEXTURE_BIT restores the bound texture's parameters, the environment and the enables.
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glDisable(GL_TEXTURE_GEN_R);
    glBindTexture(GL_TEXTURE_2D, names[2]);
    glPopAttrib();
    integers(GL_TEXTURE_BINDING_2D, 1);
    for (const GLenum name : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_WRAP_T}) {
        GLint v = 0;
        glGetTexParameteriv(GL_TEXTURE_2D, name, &v);
        values.push_back(v);
    }
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env);
    values.push_back(env[0]);
    values.push_back(glIsEnabled(GL_TEXTURE_GEN_R));
    integers(GL_MAX_TEXTURE_SIZE, 1);
    for (const GLenum name : {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_PACK_SWAP_BYTES}) integers(name, 1);
    glDeleteTextures(3, names);
    values.push_back(glIsTexture(names[1]));
    integers(GL_TEXTURE_BINDING_2D, 1);
    values.push_back(glGetError());
    return values;
}

TEST(Textures, QueriesEqualOsmesa) {
    const auto values = onBothBackends<std::vector<double>>(textureQueries);
    ASSERT_EQ(values.mygl.size(), values.osmesa.size());
    for (std::size_t i = 0; i < values.mygl.size(); ++i) EXPECT_EQ(values.mygl[i], values.osmesa[i]) << "value " << i;
}

// The GL error after each bad call, on both backends.
std::vector<GLenum> textureErrors() {
    std::vector<GLenum> errors;
    const GLubyte texel[64] = {};
    auto after = [&](const std::function<void()>& call) {
        call();
        errors.push_back(glGetError());
    };
    after([&] { glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, 0, 7, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_TRIANGLES, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_TRIANGLES, texel); });
    after([&] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel); });  // NPOT
    after([&] { glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel); });
    after([&] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_CLAMP); });
    after([&] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR); });
    after([&] { glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_LINEAR); });
    after([&] { glTexParameteri(GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, GL_LINEAR); });
    after([&] { glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR); });
    after([&] { glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_DECAL); });
    after([&] { glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP); });
    after([&] { glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_DECAL); });
    after([&] { glGenTextures(-1, nullptr); });
    after([&] { glDeleteTextures(-1, nullptr); });
    after([&] {
        glBindTexture(GL_TEXTURE_1D, 0);
        glBindTexture(GL_TEXTURE_2D, 5);
        glBindTexture(GL_TEXTURE_1D, 5);
    });
    after([&] { glBindTexture(GL_CLAMP, 0); });
    after([&] { glPixelStorei(GL_UNPACK_ROW_LENGTH, -1); });
    after([&] { glPixelStorei(GL_UNPACK_ALIGNMENT, 3); });
    after([&] { glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ENV_MODE, nullptr); });
    after([&] {
        glBegin(GL_POINTS);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
        glEnd();
    });
    return errors;
}

// The spec's error where the reference departs from it: a plane through glTexGen's scalar
// form (Mesa takes it as the plane (v, 0, 0, 0) without an error).
TEST(Textures, ScalarTexGenOfAPlaneIsAnError) {
    mygl::Context context(4, 4);
    context.makeCurrent();
    glTexGeni(GL_S, GL_OBJECT_PLANE, 1);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
}

TEST(Textures, ErrorsAsOsmesa) {
    const auto errors = onBothBackends<std::vector<GLenum>>(textureErrors);
    ASSERT_EQ(errors.mygl.size(), errors.osmesa.size());
    for (std::size_t i = 0; i < errors.mygl.size(); ++i) {
        EXPECT_EQ(errors.mygl[i], errors.osmesa[i]) << "call " << i;
    }
}

}  // namespace
