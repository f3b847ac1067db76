// gluScaleImage against closed forms, and gluBuild2DMipmaps on OSMesa (the level sizes and
// contents GL reports back) and on MyGL, which has no texture images yet: an error, no crash.
#include <gtest/gtest.h>

#include <mygl/glu.h>

#include <array>
#include <vector>

#include "backends.h"

namespace {

TEST(GluScaleImage, AveragesBoxesAndReplicates) {
    mygl::Context context(8, 8);  // GL's default pixel store: rows aligned to 4 bytes
    context.makeCurrent();
    const GLubyte in[2 * 2 * 4] = {10, 20, 30, 0, 50, 60, 70, 0, 90, 100, 110, 0, 130, 140, 150, 255};
    GLubyte one[4];
    ASSERT_EQ(gluScaleImage(GL_RGBA, 2, 2, GL_UNSIGNED_BYTE, in, 1, 1, GL_UNSIGNED_BYTE, one), 0);
    EXPECT_EQ(one[0], 70);  // (10 + 50 + 90 + 130) / 4
    EXPECT_EQ(one[2], 90);
    EXPECT_EQ(one[3], 64);  // 255 / 4 rounded
    GLfloat wide[3 * 2];
    const GLubyte pixel[1] = {51};
    ASSERT_EQ(gluScaleImage(GL_LUMINANCE, 1, 1, GL_UNSIGNED_BYTE, pixel, 3, 2, GL_FLOAT, wide), 0);
    for (GLfloat v : wide) EXPECT_FLOAT_EQ(v, 0.2f);
    // Rows of a 3-wide RGB byte image are padded to 4-byte alignment.
    const GLubyte padded[2 * 12] = {255, 0, 0,   255, 0, 0,   255, 0, 0,   99, 99, 99,
                                    0,   0, 255, 0,   0, 255, 0,   0, 255, 99, 99, 99};
    GLubyte column[2 * 4];  // 1 x 2 RGB, each row padded to 4 bytes
    ASSERT_EQ(gluScaleImage(GL_RGB, 3, 2, GL_UNSIGNED_BYTE, padded, 1, 2, GL_UNSIGNED_BYTE, column), 0);
    EXPECT_EQ((std::array<int, 3>{column[0], column[1], column[2]}), (std::array<int, 3>{255, 0, 0}));
    EXPECT_EQ((std::array<int, 3>{column[4], column[5], column[6]}), (std::array<int, 3>{0, 0, 255}));
}

template <class T>
void expectSameSizeCopiesExactly(GLenum type, T high, T low) {
    const T in[4] = {high, low, 0, high};  // 2 x 2 luminance: rows of 2 components
    T out[4] = {};
    ASSERT_EQ(gluScaleImage(GL_LUMINANCE, 2, 2, type, in, 2, 2, type, out), 0) << type;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(out[k], in[k]) << type << " " << k;
}

TEST(GluScaleImage, EveryComponentTypeCopiesItsExtremesExactly) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    expectSameSizeCopiesExactly<GLubyte>(GL_UNSIGNED_BYTE, 255, 0);
    expectSameSizeCopiesExactly<GLbyte>(GL_BYTE, 127, -127);
    expectSameSizeCopiesExactly<GLushort>(GL_UNSIGNED_SHORT, 65535, 0);
    expectSameSizeCopiesExactly<GLshort>(GL_SHORT, 32767, -32767);
    expectSameSizeCopiesExactly<GLuint>(GL_UNSIGNED_INT, 4294967295u, 0);
    expectSameSizeCopiesExactly<GLint>(GL_INT, 2147483647, -2147483647);
    expectSameSizeCopiesExactly<GLfloat>(GL_FLOAT, 3.5f, -0.25f);  // floats are not clamped
}

TEST(GluScaleImage, RejectsBadArguments) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    GLubyte in[4] = {}, out[4] = {};
    EXPECT_EQ(gluScaleImage(GL_TRIANGLES, 1, 1, GL_UNSIGNED_BYTE, in, 1, 1, GL_UNSIGNED_BYTE, out), GLU_INVALID_ENUM);
    EXPECT_EQ(gluScaleImage(GL_RGBA, 1, 1, GL_DOUBLE, in, 1, 1, GL_UNSIGNED_BYTE, out), GLU_INVALID_ENUM);
    EXPECT_EQ(gluScaleImage(GL_RGBA, -1, 1, GL_UNSIGNED_BYTE, in, 1, 1, GL_UNSIGNED_BYTE, out), GLU_INVALID_VALUE);
    EXPECT_EQ(gluScaleImage(GL_RGBA, 1, 1, GL_UNSIGNED_BYTE, nullptr, 1, 1, GL_UNSIGNED_BYTE, out), GLU_INVALID_VALUE);
    EXPECT_EQ(gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 0, 4, GL_RGBA, GL_UNSIGNED_BYTE, in), GLU_INVALID_VALUE);
    EXPECT_EQ(gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGBA, 1, GL_RGBA, GL_BITMAP, in), GLU_INVALID_ENUM);
}

TEST(GluMipmaps, OsmesaReceivesEveryLevel) {
    reference::OsmesaContext context(8, 8);
    context.makeCurrent();
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    // 5 x 3: scaled to 4 x 2, then 2 x 1 and 1 x 1. Two colours in the left and right halves.
    std::vector<GLubyte> image;
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x)
            image.insert(image.end(), {GLubyte(x < 2 ? 200 : 40), 100, GLubyte(x < 2 ? 0 : 250)});
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    ASSERT_EQ(gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 5, 3, GL_RGB, GL_UNSIGNED_BYTE, image.data()), 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const int sizes[][2] = {{4, 2}, {2, 1}, {1, 1}, {0, 0}};
    for (int level = 0; level < 4; ++level) {
        GLint w = -1, h = -1;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &h);
        EXPECT_EQ(w, sizes[level][0]) << level;
        EXPECT_EQ(h, sizes[level][1]) << level;
    }
    GLint alignment = 0;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    EXPECT_EQ(alignment, 1);  // restored
    // The 1 x 1 level is the image's mean: 2 of 5 columns of one colour, 3 of the other.
    GLubyte mean[4] = {};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 2, GL_RGB, GL_UNSIGNED_BYTE, mean);
    EXPECT_NEAR(mean[0], (2 * 200 + 3 * 40) / 5.0, 1.0);
    EXPECT_EQ(mean[1], 100);
    EXPECT_NEAR(mean[2], 3 * 250 / 5.0, 1.0);
    glDeleteTextures(1, &texture);
}

TEST(GluMipmaps, MyglWithoutTextureImagesGetsAnErrorNotACrash) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    const GLubyte image[4 * 4 * 4] = {};
    const GLint result = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, image);
    if (glTexImage2D) {
        EXPECT_EQ(result, 0);  // MyGL gained texture images: the levels went through
    } else {
        EXPECT_EQ(result, GLU_INVALID_OPERATION);
    }
    EXPECT_EQ(gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGBA, 4, GL_RGBA, GL_UNSIGNED_BYTE, image),
              glTexImage1D ? 0 : GLU_INVALID_OPERATION);
}

}  // namespace
