// glBitmap, glDrawPixels and glCopyPixels under an enabled texture against OSMesa: the reference
// textures a bitmap's fragments with the current texture coordinates as a constant, or, when
// something may make them vary (a texture matrix, texture generation, coordinates in the last
// draw's vertex format), with the coordinates of the quad it draws the bitmap (or its cache of
// bitmaps) with; an image's fragments always with the current coordinates as a constant
// (docs/reference-rules.md, "Textured bitmaps"). Every frame is compared bit for bit.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::differingPixels;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

constexpr int kWidth = 96, kHeight = 48;

// A 4 x 1 texture of red, green, blue and white (the probe's), `filter` both ways.
void stripTexture(GLenum filter) {
    const GLubyte texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
}

// A 16 x 16 RGB texture with every mipmap level, each level its own colours (the level a
// fragment samples shows), LINEAR_MIPMAP_LINEAR.
void mipmappedTexture() {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0, side = 16; side >= 1; ++level, side /= 2) {
        std::vector<GLubyte> texels;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                texels.insert(texels.end(), {GLubyte(x * 255 / side), GLubyte(y * 255 / side), GLubyte(60 * level)});
            }
        }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

// `glyphs` bitmaps of 9 x 13 random bits (rows 4-byte aligned, the unpack alignment) in a row
// from the raster position, each moving it 10 pixels right, as glutBitmapCharacter draws text.
void text(int glyphs, unsigned seed) {
    std::mt19937 random(seed);
    std::vector<GLubyte> bits(4 * 13);
    for (int g = 0; g < glyphs; ++g) {
        for (GLubyte& b : bits) b = static_cast<GLubyte>(random());
        glBitmap(9, 13, 0.0f, 2.0f, 10.0f, 0.0f, bits.data());
    }
}

// A window-sized orthographic view, cleared; the raster colour (0.8, 0.6, 1.0).
void setUp() {
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.8f, 0.6f, 1.0f);
}

// A quad with texture coordinates per vertex (its draw makes them vary for later bitmaps).
void texturedQuad() {
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0), glVertex2f(60, 2);
    glTexCoord2f(1, 0), glVertex2f(90, 2);
    glTexCoord2f(1, 1), glVertex2f(90, 12);
    glTexCoord2f(0, 1), glVertex2f(60, 12);
    glEnd();
}

struct Case {
    std::string name;
    std::function<void()> draw;
};

std::vector<Case> cases() {
    const auto strip = [](GLenum filter, std::function<void()> beforeText) {
        return [=] {
            setUp();
            stripTexture(filter);
            glEnable(GL_TEXTURE_2D);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
            glTexCoord2f(0.6f, 0.5f);
            beforeText();
            glRasterPos2i(3, 20);
            text(7, 1);
        };
    };
    return {
        {"constant coordinates, linear", strip(GL_LINEAR, [] {})},
        {"constant coordinates, nearest", strip(GL_NEAREST, [] {})},
        {"coordinates changed after the raster position",
         [] {
             setUp();
             stripTexture(GL_LINEAR);
             glEnable(GL_TEXTURE_2D);
             glRasterPos2i(3, 20);
             glTexCoord2f(0.1f, 0.5f);
             text(5, 2);
         }},
        {"a texture matrix: the cache's coordinates", strip(GL_LINEAR,
                                                            [] {
                                                                glMatrixMode(GL_TEXTURE);
                                                                glTranslatef(0.25f, 0, 0);
                                                                glMatrixMode(GL_MODELVIEW);
                                                            })},
        {"texture generation: the cache's coordinates", strip(GL_LINEAR, [] { glEnable(GL_TEXTURE_GEN_S); })},
        {"a textured draw before: the cache's coordinates", strip(GL_LINEAR, texturedQuad)},
        {"a textured draw, then an untextured state change", strip(GL_NEAREST,
                                                                   [] {
                                                                       texturedQuad();
                                                                       glShadeModel(GL_FLAT);
                                                                   })},
        {"an untextured draw before: constant", strip(GL_LINEAR,
                                                      [] {
                                                          glBegin(GL_TRIANGLES);
                                                          glVertex2f(60, 2), glVertex2f(90, 2), glVertex2f(90, 12);
                                                          glEnd();
                                                      })},
        {"mipmapped, text after a textured draw (a HUD over a scene)",
         [] {
             setUp();
             mipmappedTexture();
             glEnable(GL_TEXTURE_2D);
             texturedQuad();
             glRasterPos2i(2, 30);
             text(9, 3);
             glRasterPos2i(2, 10);  // the second line starts a new cache (below the first)
             text(6, 4);
         }},
        {"mipmapped, replace, constant",
         [] {
             setUp();
             mipmappedTexture();
             glEnable(GL_TEXTURE_2D);
             glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
             glTexCoord2f(0.3f, 0.7f);
             glRasterPos2i(2, 30);
             text(9, 5);
         }},
        {"fog and blending over a textured draw",
         [] {
             setUp();
             mipmappedTexture();
             glEnable(GL_TEXTURE_2D);
             texturedQuad();
             glEnable(GL_FOG);
             glFogi(GL_FOG_MODE, GL_LINEAR);
             glFogf(GL_FOG_START, -1.0f);
             glFogf(GL_FOG_END, 2.0f);
             glEnable(GL_BLEND);
             glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
             glColor4f(0.9f, 0.5f, 0.2f, 0.6f);
             glRasterPos2i(2, 20);
             text(8, 6);
         }},
        {"a bitmap larger than the cache: its own quad",
         [] {
             setUp();
             mipmappedTexture();
             glEnable(GL_TEXTURE_2D);
             texturedQuad();
             glRasterPos2i(1, 4);
             std::vector<GLubyte> bits(4 * 40, 0xA5);
             glBitmap(16, 40, 0, 0, 0, 0, bits.data());
         }},
    };
}

}  // namespace

TEST(TexturedBitmaps, FragmentsTakeTheReferencesTextureCoordinates) {
    for (const Case& c : cases()) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                c.draw();
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0) << c.name;
    }
}

namespace {

// A 5 x 3 texture of `base` (random texels) with `env`, `filter` both ways.
void smallTexture(GLenum base, GLenum env, GLenum filter, unsigned seed) {
    std::mt19937 random(seed);
    std::vector<GLubyte> texels(5 * 3 * 4);
    for (GLubyte& t : texels) t = static_cast<GLubyte>(random());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(base), 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(env));
    const GLfloat envColor[] = {0.3f, 0.7f, 0.45f, 0.6f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
}

// A 20 x 9 image of random RGBA bytes drawn zoomed at (2, 3) and copied to (50, 20).
void images(unsigned seed) {
    std::mt19937 random(seed);
    std::vector<GLubyte> pixels(20 * 9 * 4);
    for (GLubyte& p : pixels) p = static_cast<GLubyte>(random());
    glRasterPos2i(2, 3);
    glPixelZoom(1.5f, 2.0f);
    glDrawPixels(20, 9, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glPixelZoom(1.0f, 1.0f);
    glRasterPos2i(50, 20);
    glCopyPixels(2, 3, 30, 18, GL_COLOR);
}

}  // namespace

TEST(TexturedPixelImages, DrawnAndCopiedImagesTakeTheCurrentCoordinatesAsAConstant) {
    const GLenum bases[] = {GL_RGB, GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY};
    const GLenum envs[] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD};
    unsigned seed = 1;
    for (GLenum base : bases) {
        for (GLenum env : envs) {
            for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
                ++seed;
                const auto frames = onBothBackends<Frame>(
                    [&] {
                        setUp();
                        smallTexture(base, env, filter, seed);
                        glEnable(GL_TEXTURE_2D);
                        if (seed % 3 == 0) texturedQuad();  // the coordinates stay constant all the same
                        if (seed % 4 == 0) {                // and under a texture matrix
                            glMatrixMode(GL_TEXTURE);
                            glRotatef(30.0f, 0, 0, 1);
                            glMatrixMode(GL_MODELVIEW);
                        }
                        if (seed % 7 == 0) {  // linear fog (the images' fog coordinate is 0: 2/3 here)
                            glEnable(GL_FOG);
                            glFogi(GL_FOG_MODE, GL_LINEAR);
                            glFogf(GL_FOG_START, -1.0f);
                            glFogf(GL_FOG_END, 2.0f);
                        }
                        glTexCoord4f(0.37f, 0.61f, 0.0f, seed % 5 == 0 ? 1.5f : 1.0f);
                        images(seed);
                        return readFrame(kWidth, kHeight);
                    },
                    kWidth, kHeight);
                EXPECT_EQ(differingPixels(frames.mygl, frames.osmesa), 0)
                    << "base " << base << " env " << env << " filter " << filter << " seed " << seed;
            }
        }
    }
}
