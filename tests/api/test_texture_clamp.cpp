// GL_CLAMP under LINEAR filters: the reference's float sampler blends the border colour at the
// edges. Every filter pair with mipmaps, border colours (default, others, out of range), every
// base format, GL_CLAMP on one axis only, non-power-of-two sizes, 1D textures and images given
// with a border, each frame's colour and depth compared with OSMesa running the same calls.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <array>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::difference;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 96, kHeight = 72;
constexpr GLenum kClampToEdge = 0x812F;

// Bytes of a width x height image of `components` per texel, its colours varying per texel and
// per level so that the blended texels and the level show.
std::vector<GLubyte> image(int width, int height, int components, int level) {
    std::vector<GLubyte> texels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const bool check = (x + y) % 2 == 0;
            const GLubyte bytes[4] = {
                static_cast<GLubyte>(check ? 220 : 25 + 23 * x), static_cast<GLubyte>(250 * y / std::max(height, 1)),
                static_cast<GLubyte>(35 * level + 7 * x), static_cast<GLubyte>(check ? 255 : 70 + 13 * y)};
            texels.insert(texels.end(), bytes, bytes + components);
        }
    }
    return texels;
}

struct ClampCase {
    GLenum minFilter = GL_LINEAR, magFilter = GL_LINEAR;
    GLenum wrapS = GL_CLAMP, wrapT = GL_CLAMP;
    std::array<GLfloat, 4> border{0.9f, 0.3f, 0.6f, 0.8f};
    GLint internalFormat = GL_RGBA;
    GLenum format = GL_RGBA;
    int components = 4;
    int width = 8, height = 8;
    GLenum env = GL_MODULATE;
    bool oneDimensional = false;
};

std::string describe(const ClampCase& c) {
    return "min " + std::to_string(c.minFilter) + " mag " + std::to_string(c.magFilter) + " wraps " +
           std::to_string(c.wrapS) + "/" + std::to_string(c.wrapT) + " border " + std::to_string(c.border[0]) + "," +
           std::to_string(c.border[1]) + "," + std::to_string(c.border[2]) + "," + std::to_string(c.border[3]) +
           " internal " + std::to_string(c.internalFormat) + " " + std::to_string(c.width) + "x" +
           std::to_string(c.height) + " env " + std::to_string(c.env) + (c.oneDimensional ? " 1D" : " 2D");
}

// A floor going away (magnified near, minified far) and a small magnified triangle, their
// coordinates beyond [0, 1] so that the border shows; every mipmap level given.
Frame drawClamped(const ClampCase& c) {
    testing_support::clearedPerspectiveView(0.0f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const GLenum target = c.oneDimensional ? GL_TEXTURE_1D : GL_TEXTURE_2D;
    for (int level = 0, w = c.width, h = c.height; w >= 1 || h >= 1; ++level, w /= 2, h /= 2) {
        const int lw = std::max(w, 1), lh = c.oneDimensional ? 1 : std::max(h, 1);
        const std::vector<GLubyte> texels = image(lw, lh, c.components, level);
        if (c.oneDimensional) {
            glTexImage1D(target, level, c.internalFormat, lw, 0, c.format, GL_UNSIGNED_BYTE, texels.data());
        } else {
            glTexImage2D(target, level, c.internalFormat, lw, lh, 0, c.format, GL_UNSIGNED_BYTE, texels.data());
        }
        if (w <= 1 && (h <= 1 || c.oneDimensional)) break;
    }
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(c.minFilter));
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(c.magFilter));
    glTexParameteri(target, GL_TEXTURE_WRAP_S, static_cast<GLint>(c.wrapS));
    glTexParameteri(target, GL_TEXTURE_WRAP_T, static_cast<GLint>(c.wrapT));
    glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, c.border.data());
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(c.env));
    const GLfloat envColor[] = {0.2f, 0.7f, 0.4f, 0.6f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
    glEnable(target);
    glBegin(GL_QUADS);
    const float corners[4][5] = {{-2.0f, -1.0f, -1.5f, -0.4f, -0.3f},
                                 {2.0f, -1.0f, -1.5f, 1.5f, -0.3f},
                                 {2.0f, -1.0f, -30.0f, 1.5f, 5.0f},
                                 {-2.0f, -1.0f, -30.0f, -0.4f, 5.0f}};
    for (int i = 0; i < 4; ++i) {
        glColor4f(0.5f + 0.15f * float(i), 1.0f - 0.2f * float(i), 0.6f, 0.9f);
        glTexCoord2f(corners[i][3], corners[i][4]);
        glVertex3f(corners[i][0], corners[i][1], corners[i][2]);
    }
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.7f, 0.4f);
    glTexCoord2f(-0.2f, -0.1f);
    glVertex3f(-0.5f, 0.0f, -2.0f);
    glColor3f(0.3f, 1.0f, 0.8f);
    glTexCoord2f(1.3f, 0.1f);
    glVertex3f(0.6f, -0.1f, -2.2f);
    glColor3f(0.8f, 0.5f, 1.0f);
    glTexCoord2f(0.6f, 1.25f);
    glVertex3f(0.1f, 0.7f, -2.4f);
    glEnd();
    glDisable(target);
    return readFrame(kWidth, kHeight);
}

void expectIdentical(const ClampCase& c) {
    const auto frames = onBothBackends<Frame>([&] { return drawClamped(c); }, kWidth, kHeight);
    const testing_support::ColorDifference d = difference(frames.mygl, frames.osmesa);
    EXPECT_EQ(d.pixels, 0) << describe(c) << ": max channel difference " << d.maxChannel;
}

TEST(TextureClamp, EveryFilterPairBlendsTheBorder) {
    const GLenum minFilters[] = {GL_NEAREST,
                                 GL_LINEAR,
                                 GL_NEAREST_MIPMAP_NEAREST,
                                 GL_LINEAR_MIPMAP_NEAREST,
                                 GL_NEAREST_MIPMAP_LINEAR,
                                 GL_LINEAR_MIPMAP_LINEAR};
    for (const GLenum minFilter : minFilters) {
        for (const GLenum magFilter : {GL_NEAREST, GL_LINEAR}) {
            ClampCase c;
            c.minFilter = minFilter, c.magFilter = magFilter;
            expectIdentical(c);
        }
    }
}

TEST(TextureClamp, BorderColoursAndEnvironments) {
    const std::array<GLfloat, 4> borders[] = {
        {0.0f, 0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f, 1.0f}, {0.25f, 0.5f, 0.75f, 0.1f}, {1.5f, -0.2f, 0.333f, 2.0f}};
    for (const auto& border : borders) {
        for (const GLenum env : {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD}) {
            ClampCase c;
            c.border = border, c.env = env;
            expectIdentical(c);
        }
    }
}

TEST(TextureClamp, BaseFormatsTakeTheBorderAsTheirs) {
    struct Format {
        GLint internal;
        GLenum format;
        int components;
    };
    const Format formats[] = {{GL_ALPHA, GL_ALPHA, 1},
                              {GL_LUMINANCE, GL_LUMINANCE, 1},
                              {GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, 2},
                              {GL_INTENSITY, GL_LUMINANCE, 1},
                              {GL_RGB, GL_RGB, 3},
                              {GL_RGBA, GL_RGBA, 4}};
    for (const Format& f : formats) {
        for (const GLenum env : {GL_MODULATE, GL_REPLACE, GL_BLEND}) {
            ClampCase c;
            c.internalFormat = f.internal, c.format = f.format, c.components = f.components, c.env = env;
            expectIdentical(c);
        }
    }
}

TEST(TextureClamp, OneAxisClampedNonPowerOfTwoSizes) {
    for (const GLenum other : {GLenum{GL_REPEAT}, kClampToEdge, GLenum{GL_CLAMP}}) {
        for (const std::array<int, 2> size : {std::array<int, 2>{8, 8}, {5, 7}, {12, 3}}) {
            for (const GLenum minFilter : {GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR}) {
                ClampCase c;
                c.minFilter = minFilter;
                c.width = size[0], c.height = size[1];
                c.wrapT = other;
                expectIdentical(c);
                c.wrapS = other, c.wrapT = GL_CLAMP;
                expectIdentical(c);
            }
        }
    }
}

TEST(TextureClamp, OneDimensional) {
    const GLenum minFilters[] = {GL_LINEAR, GL_NEAREST, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_LINEAR};
    for (const GLenum minFilter : minFilters) {
        for (const GLenum magFilter : {GL_NEAREST, GL_LINEAR}) {
            for (const int width : {16, 6}) {
                ClampCase c;
                c.oneDimensional = true;
                c.minFilter = minFilter, c.magFilter = magFilter, c.width = width, c.height = 1;
                expectIdentical(c);
            }
        }
    }
}

// An image given with a one-texel border: the reference strips it and blends the border colour.
TEST(TextureClamp, ImageBorderTexelsAreNotSampled) {
    const auto frames = onBothBackends<Frame>(
        [] {
            testing_support::clearedPerspectiveView(2.0f);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            const std::vector<GLubyte> texels = image(10, 10, 4, 0);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 10, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
            const GLfloat border[] = {0.1f, 0.8f, 0.2f, 1.0f};
            glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
            glEnable(GL_TEXTURE_2D);
            glBegin(GL_QUADS);
            glTexCoord2f(-0.25f, -0.25f), glVertex3f(-1.0f, -1.0f, 0.0f);
            glTexCoord2f(1.25f, -0.25f), glVertex3f(1.0f, -1.0f, 0.0f);
            glTexCoord2f(1.25f, 1.25f), glVertex3f(1.0f, 1.0f, 0.0f);
            glTexCoord2f(-0.25f, 1.25f), glVertex3f(-1.0f, 1.0f, 0.0f);
            glEnd();
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    EXPECT_EQ(difference(frames.mygl, frames.osmesa).pixels, 0);
}

}  // namespace
