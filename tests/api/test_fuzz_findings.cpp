// What the differential fuzzer found in the texture, pixel and per-fragment calls (issue 12),
// each shrunk to its calls and compared with OSMesa running them.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <limits>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

// A 2D texture whose border leaves no rows inside (height 2, border 1; the fuzzer's seed 13: MyGL
// took it for one row and read past its texels in glGetTexImage). The spec: a 16 x 0 image,
// GL_TEXTURE_WIDTH 18 with the border, nothing to write. OSMesa departs (Mesa's
// strip_texture_border keeps a height below 3 and drops the width's border: a 16 x 2 image, width
// 16; docs/reference-rules.md), so only the errors are compared with it.
TEST(FuzzFindings, TextureWithBorderAndNoInteriorRowsHasAnEmptyImage) {
    struct Answers {
        GLint width = 0, height = 0;
        GLenum error = GL_NO_ERROR;
        std::vector<GLubyte> image;
    };
    const auto results = onBothBackends<Answers>([] {
        std::vector<GLubyte> data(18 * 2 * 4, 200);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 18, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
        Answers a;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &a.width);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &a.height);
        a.image.assign(18 * 2 * 4, 0x5A);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, a.image.data());
        a.error = glGetError();
        return a;
    });
    EXPECT_EQ(results.mygl.error, results.osmesa.error);
    EXPECT_EQ(results.mygl.width, 18);
    EXPECT_EQ(results.mygl.height, 2);
    EXPECT_EQ(results.mygl.image, std::vector<GLubyte>(18 * 2 * 4, 0x5A));
    // The departure as recorded: OSMesa's image is 16 x 2, its rows written.
    EXPECT_EQ(results.osmesa.width, 16);
    EXPECT_EQ(results.osmesa.image[16 * 2 * 4 - 1], 200);
}

// A user clip plane culls the raster position as it culls a point (the fuzzer's seed 9: MyGL kept
// a position outside GL_CLIP_PLANE0 valid and drew the bitmap there).
TEST(FuzzFindings, UserClipPlanesInvalidateTheRasterPosition) {
    const auto results = onBothBackends<std::vector<GLfloat>>([] {
        const GLdouble plane[] = {1, 0, 0, 0.25};  // x >= -0.25, in eye space
        glClipPlane(GL_CLIP_PLANE0, plane);
        glEnable(GL_CLIP_PLANE0);
        glMatrixMode(GL_PROJECTION);
        glOrtho(-1, 1, -1, 1, -1, 1);  // the plane follows the projection too
        glMatrixMode(GL_MODELVIEW);
        const std::vector<GLubyte> bits(8 * 4, 0xFF);  // 8 rows of 4 bytes (GL_UNPACK_ALIGNMENT 4)
        std::vector<GLfloat> answers;
        for (GLfloat x : {-0.75f, -0.25f, 0.5f}) {
            glRasterPos2f(x, 0.0f);
            GLfloat valid = 0;
            glGetFloatv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
            answers.push_back(valid);
            glBitmap(8, 8, 0, 0, 0, 0, bits.data());
        }
        std::vector<GLubyte> pixels(16 * 16 * 4);
        glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        answers.insert(answers.end(), pixels.begin(), pixels.end());
        return answers;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
    EXPECT_EQ(results.osmesa[0], 0.0f);  // the case shows: the first position is culled
}

// glGenTextures hands out names after the largest ever given or bound, deleted or not (the
// fuzzer's seed 13: MyGL gave 1 after name 2 was bound and deleted; OSMesa gives 3).
TEST(FuzzFindings, GeneratedTextureNamesFollowTheLargestNameEverUsed) {
    const auto results = onBothBackends<std::vector<GLuint>>([] {
        std::vector<GLuint> names(5);
        glBindTexture(GL_TEXTURE_2D, 2);
        const GLuint two = 2;
        glDeleteTextures(1, &two);
        glGenTextures(2, names.data());
        glDeleteTextures(2, names.data());
        glGenTextures(1, &names[2]);
        glBindTexture(GL_TEXTURE_1D, 9);
        glGenTextures(2, &names[3]);
        return names;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
}

// A depth clear the reference makes with a quad (scissored, or with the stencil under a partial
// write mask) rounds the clear value through float (the fuzzer's seed 42: glStencilMask(1), then
// glClear of depth and stencil at depth 0.51744331 gave 8681257, MyGL 8681258).
TEST(FuzzFindings, DepthClearedWithAQuadTakesTheFloatPath) {
    const auto results = onBothBackends<std::vector<GLuint>>(
        [] {
            std::vector<GLuint> depths;
            for (int mode = 0; mode < 3; ++mode) {
                for (double d : {0.51744331097978524, 0.3, 0.123456789, 0.9999, 0.00001, 0.7}) {
                    glClearDepth(d);
                    glStencilMask(mode == 0 ? 1 : 0xFF);
                    if (mode == 1) glEnable(GL_SCISSOR_TEST);
                    glScissor(0, 0, mode == 2 ? 4 : 2, mode == 2 ? 4 : 2);  // mode 2: the whole window
                    glClear(GL_DEPTH_BUFFER_BIT | (mode == 0 ? GL_STENCIL_BUFFER_BIT : 0));
                    GLuint z = 0;
                    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
                    depths.push_back(z);
                }
            }
            return depths;
        },
        4, 4);
    EXPECT_EQ(results.mygl, results.osmesa);
}

// A lit glRasterPos before the first lit draw (the fuzzer's seed 78: the raster position prepared
// the lighting without handing it to the pipeline, so the point after it was drawn unlit).
TEST(FuzzFindings, LitRasterPositionLeavesTheNextDrawLit) {
    const auto results = onBothBackends<std::vector<GLubyte>>(
        [] {
            glEnable(GL_LIGHTING);
            glRasterPos4i(1, 1, 0, 1);
            glBegin(GL_POINTS);
            glVertex4i(0, 0, 0, 1);
            glEnd();
            std::vector<GLubyte> pixels(2 * 2 * 4);
            glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
            return pixels;
        },
        2, 2);
    EXPECT_EQ(results.mygl, results.osmesa);
}

// glCopyPixels of a rectangle far larger than the window (the fuzzer's seed 214: MyGL ran out of
// memory making its 30 x 10^9 image). A plain copy is a blit of the part in the window, as the
// reference's; one drawn through the fragment operations copies nothing in MyGL (the reference
// draws its rectangle as zeros: rule copy-pixels-beyond-texture-size in the fuzzer).
TEST(FuzzFindings, CopyPixelsOfAHugeRectangle) {
    const auto results = onBothBackends<std::vector<GLubyte>>([] {
        glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1, 0, 0);
        glRectf(-1, -1, 0, 0);
        glRasterPos2f(0.25f, 0.25f);
        glCopyPixels(0, 0, 30, 1000000000, GL_COLOR);  // a blit
        std::vector<GLubyte> pixels(16 * 16 * 4);
        glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        glPixelZoom(1.0f, -1.0f);
        glCopyPixels(0, 0, 30, 1000000000, GL_COLOR);  // drawn
        glCopyPixels(0, 0, 1000000000, 4, GL_DEPTH);
        std::vector<GLubyte> after(16 * 16 * 4);
        glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, after.data());
        pixels.push_back(after == pixels);
        return pixels;
    });
    EXPECT_EQ(std::vector<GLubyte>(results.mygl.begin(), results.mygl.end() - 1),
              std::vector<GLubyte>(results.osmesa.begin(), results.osmesa.end() - 1));
    EXPECT_EQ(results.mygl.back(), 1);  // the drawn copies left the frame as it was
}

// glGetTexImage as floats: each byte times 1/255, as the reference converts it (the fuzzer's
// seed 294: MyGL divided by 255, an ulp off for 126 of the 256 values).
TEST(FuzzFindings, TextureBytesReadAsFloatsAreTimesOneOver255) {
    const auto results = onBothBackends<std::vector<GLfloat>>([] {
        std::vector<GLubyte> bytes(256 * 4);
        for (int i = 0; i < 256 * 4; ++i) bytes[static_cast<std::size_t>(i)] = static_cast<GLubyte>(i / 4);
        std::vector<GLfloat> floats;
        for (GLint internal : {GL_LUMINANCE, GL_RGBA8}) {
            glTexImage2D(GL_TEXTURE_2D, 0, internal, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
            std::vector<GLfloat> image(256 * 4);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, image.data());
            floats.insert(floats.end(), image.begin(), image.end());
        }
        return floats;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
}

// A point, a glDrawPixels, then an empty glBegin/glEnd (the fuzzer's seed 160): the point's
// flush forgot the image's texture, which the empty block's state then freed while its quad was
// still queued (the pixel took freed memory's colour).
TEST(FuzzFindings, ImageDrawnAfterAPointKeepsItsTextureUntilDrawn) {
    const auto results = onBothBackends<std::vector<GLubyte>>(
        [] {
            glClear(GL_COLOR_BUFFER_BIT);
            glBegin(GL_POINTS);
            glVertex2d(0.0, 0.0);
            glEnd();
            const GLubyte image[4] = {10, 200, 30, 255};
            glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
            glBegin(GL_POINTS);
            glEnd();
            std::vector<GLubyte> pixel(4);
            glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
            return pixel;
        },
        1, 1);
    EXPECT_EQ(results.mygl, results.osmesa);
}

// A call with several errors records the one the reference checks first (GL leaves the choice
// open; the fuzzer's seeds 500, 528, 733, 949): glTexImage's format and type before its internal
// format and size, glTexSubImage's negative size before an undefined level, glPixelMap's size
// before its map.
TEST(FuzzFindings, CallsWithSeveralErrorsRecordTheReferencesFirst) {
    const auto results = onBothBackends<std::vector<GLenum>>([] {
        std::vector<GLubyte> data(4100, 7);
        const GLfloat values[16] = {};
        std::vector<GLenum> errors;
        glTexImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 1, 0, 0, data.data());
        errors.push_back(glGetError());
        glTexImage2D(GL_TEXTURE_2D, 1, 0, 0, 0, 1, 0, 0, data.data());
        errors.push_back(glGetError());
        glTexImage2D(GL_TEXTURE_2D, 0, 0, 3, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, data.data());
        errors.push_back(glGetError());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 3, 0, GL_DEPTH_COMPONENT, GL_FLOAT, data.data());
        errors.push_back(glGetError());
        glTexImage1D(GL_TEXTURE_1D, 0, 0, -1, 0, GL_RGBA, 0, data.data());
        errors.push_back(glGetError());
        glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, -1, 0, 0, 0, data.data());
        errors.push_back(glGetError());
        glPixelMapfv(0, 0, values);
        errors.push_back(glGetError());
        glPixelMapfv(0, 3, values);
        errors.push_back(glGetError());
        return errors;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
}

// glReadPixels of GL_LUMINANCE_ALPHA under a pixel transfer clamps the alpha to [0, 1] as it
// clamps the colours it sums (the fuzzer's seed 743: an alpha bias of 1.24 read as floats).
TEST(FuzzFindings, LuminanceAlphaReadUnderATransferClampsAlpha) {
    const auto results = onBothBackends<std::vector<GLfloat>>([] {
        glClearColor(0.2f, 0.3f, 0.4f, 0.5f);
        glClear(GL_COLOR_BUFFER_BIT);
        std::vector<GLfloat> read;
        for (GLfloat bias : {1.23936641f, -0.9f}) {
            glPixelTransferf(GL_ALPHA_BIAS, bias);
            GLfloat pixel[2] = {};
            glReadPixels(0, 0, 1, 1, GL_LUMINANCE_ALPHA, GL_FLOAT, pixel);
            read.insert(read.end(), pixel, pixel + 2);
        }
        return read;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
}

// A NaN colour component is drawn as 0 when the colour is not in the vertex format (the current
// colour, given outside glBegin/glEnd: the reference takes it as a constant), and as 1 when the
// vertices carry it (its vertex stage saturates them). The fuzzer's seed 623: glColor4f(0, 0,
// NaN, 0); glRectf drew blue 255.
TEST(FuzzFindings, NanColourIsZeroUnlessTheVerticesCarryIt) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const auto results = onBothBackends<std::vector<GLubyte>>(
        [nan] {
            std::vector<GLubyte> pixels;
            for (int variant = 0; variant < 4; ++variant) {
                glClear(GL_COLOR_BUFFER_BIT);
                if (variant == 0) {  // the current colour
                    glColor4f(0.5f, 0.5f, nan, 1.0f);
                    glRectf(-1, -1, 1, 1);
                } else if (variant == 1) {  // per vertex
                    glBegin(GL_POINTS);
                    glColor4f(0.5f, nan, 0.5f, 1.0f);
                    glVertex2f(0, 0);
                    glEnd();
                } else if (variant == 2) {  // the current colour again (glClear forgot the format)
                    glColor4f(0.5f, 0.5f, 0.5f, nan);
                    glBegin(GL_POINTS);
                    glVertex2f(0, 0);
                    glEnd();
                } else {
                    glShadeModel(GL_FLAT);
                    glColor4f(nan, 0.5f, 0.5f, 1.0f);
                    glBegin(GL_TRIANGLES);
                    glVertex2f(-1, -1), glVertex2f(3, -1), glVertex2f(-1, 3);
                    glEnd();
                }
                pixels.resize(pixels.size() + 4);
                glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data() + pixels.size() - 4);
            }
            return pixels;
        },
        1, 1);
    EXPECT_EQ(results.mygl, results.osmesa);
}

// NaN in LIT's inputs lights with the ambient term only, as the reference's LIT does (x > 0 and
// max(y, 0) fail over to 0): an infinite normal under GL_LIGHT7 with shininess 1 (the fuzzer's
// seed 610), and a local viewer's half vector of a vertex on the eye axis, normalize(0, 0, 0)
// (seed 977). MyGL's NaN weights made the colour NaN, saturated to 255.
TEST(FuzzFindings, NanLightingProductsLeaveTheAmbientTerm) {
    const auto results = onBothBackends<std::vector<GLubyte>>(
        [] {
            std::vector<GLubyte> pixels;
            for (int variant = 0; variant < 2; ++variant) {
                glClear(GL_COLOR_BUFFER_BIT);
                glEnable(GL_LIGHTING);
                glEnable(variant == 0 ? GL_LIGHT7 : GL_LIGHT1);
                glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 1.0f);
                glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, variant);
                glBegin(GL_POINTS);
                if (variant == 0) {
                    glNormal3d(-1e300, 0.0, 0.0);
                    glVertex2f(0, 0);
                } else {
                    glVertex4i(0, 0, 1, 1);
                }
                glEnd();
                glDisable(variant == 0 ? GL_LIGHT7 : GL_LIGHT1);
                pixels.resize(pixels.size() + 4);
                glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data() + pixels.size() - 4);
            }
            return pixels;
        },
        1, 1);
    EXPECT_EQ(results.mygl, results.osmesa);
}

}  // namespace
