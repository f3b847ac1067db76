// glRasterPos and glBitmap against OSMesa: the raster position, its valid bit, colour, distance
// and texture coordinates after every kind of transform, the bitmaps' pixels (placement,
// rounding of the position, cutting at the window, unpack alignment, colour conversion, depth
// test and depth writes) and the errors. Every case is compared bit for bit.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

constexpr int kWidth = 48, kHeight = 40;

// Everything glGet says about the raster position, as floats (exact in both backends).
std::vector<GLfloat> rasterState() {
    std::vector<GLfloat> values(14);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, &values[0]);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, &values[4]);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &values[8]);
    GLboolean valid = GL_FALSE;
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    values[9] = valid;
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, &values[10]);
    return values;
}

struct Frame {
    std::vector<GLubyte> color;
    std::vector<GLuint> depth;
    std::vector<GLfloat> raster;
    GLenum error = GL_NO_ERROR;
};

Frame readFrame() {
    Frame frame{std::vector<GLubyte>(kWidth * kHeight * 4), std::vector<GLuint>(kWidth * kHeight), rasterState(),
                glGetError()};
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, frame.color.data());
    glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, frame.depth.data());
    return frame;
}

// 11 x 7 bits, an irregular pattern so that a flipped or shifted bitmap shows.
const GLubyte kGlyph[7 * 2] = {0xF1, 0x20, 0x80, 0xE0, 0x41, 0x40, 0x22, 0x00, 0x14, 0x20, 0x08, 0xA0, 0xFF, 0x60};
// The same glyph with its rows 8-byte aligned.
const GLubyte kGlyphAligned8[7 * 8] = {0xF1, 0x20, 0,    0,    0,    0, 0, 0, 0x80, 0xE0, 0,    0,    0, 0, 0,
                                       0,    0x41, 0x40, 0,    0,    0, 0, 0, 0,    0x22, 0x00, 0,    0, 0, 0,
                                       0,    0,    0x14, 0x20, 0,    0, 0, 0, 0,    0,    0x08, 0xA0, 0, 0, 0,
                                       0,    0,    0,    0xFF, 0x60, 0, 0, 0, 0,    0,    0};

void perspectiveView() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.5, 0.5, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.1f, -0.2f, -3.0f);
    glRotatef(33.0f, 0.4f, 1.0f, 0.2f);
}

void expectSame(const testing_support::BothResults<Frame>& frames, const std::string& what) {
    EXPECT_EQ(frames.mygl.raster, frames.osmesa.raster) << what;
    EXPECT_EQ(frames.mygl.error, frames.osmesa.error) << what;
    EXPECT_EQ(frames.mygl.color, frames.osmesa.color) << what;
    EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << what;
}

}  // namespace

TEST(RasterPos, PositionColorDistanceAndTexCoordsAsTheReference) {
    struct Case {
        const char* name;
        void (*set)();
    };
    const Case cases[] = {
        {"identity, 2f", [] { glRasterPos2f(0.25f, -0.7f); }},
        {"identity, 3d", [] { glRasterPos3d(-0.33, 0.41, 0.77); }},
        {"identity, 4f with w", [] { glRasterPos4f(0.3f, 0.2f, 0.1f, 2.0f); }},
        {"identity, 2i corner", [] { glRasterPos2i(1, 1); }},
        {"identity, 3sv",
         [] {
             const GLshort v[3] = {0, 0, 1};
             glRasterPos3sv(v);
         }},
        {"perspective, 3fv",
         [] {
             perspectiveView();
             const GLfloat v[3] = {0.3f, 0.45f, -0.2f};
             glRasterPos3fv(v);
         }},
        {"perspective, 4dv",
         [] {
             perspectiveView();
             const GLdouble v[4] = {0.5, -0.25, 0.125, 1.5};
             glRasterPos4dv(v);
         }},
        {"viewport and depth range",
         [] {
             glViewport(5, 3, 30, 21);
             glDepthRange(0.2, 0.7);
             glRasterPos3f(0.6f, -0.3f, 0.45f);
         }},
        {"texture matrix and texcoord",
         [] {
             glMatrixMode(GL_TEXTURE);
             glScalef(2.0f, 0.5f, 1.0f);
             glTexCoord2f(0.3f, 0.8f);
             glRasterPos2f(0.0f, 0.0f);
         }},
        {"colour taken at glRasterPos, not later",
         [] {
             glColor4f(0.2f, 0.9f, 0.45f, 0.6f);
             glRasterPos2f(0.1f, 0.1f);
             glColor3f(1.0f, 0.0f, 0.0f);
         }},
        {"outside left: invalid, the rest kept",
         [] {
             glColor3f(0.5f, 0.5f, 0.5f);
             glRasterPos2f(0.5f, 0.5f);
             glColor3f(0.1f, 0.2f, 0.3f);
             glRasterPos2f(-1.01f, 0.0f);
         }},
        {"on the right edge: valid", [] { glRasterPos2f(1.0f, 0.0f); }},
        {"behind the near plane: invalid",
         [] {
             perspectiveView();
             glRasterPos3f(0.0f, 0.0f, 10.0f);
         }},
        {"beyond the far plane: invalid", [] { glRasterPos3f(0.0f, 0.0f, -1.001f); }},
        {"valid again after invalid",
         [] {
             glRasterPos2f(3.0f, 0.0f);
             glRasterPos2f(0.2f, 0.3f);
         }},
    };
    for (const Case& c : cases) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                c.set();
                return readFrame();
            },
            kWidth, kHeight);
        expectSame(frames, c.name);
    }
}

TEST(Bitmap, PixelsMovesDepthAndErrorsAsTheReference) {
    struct Case {
        const char* name;
        void (*draw)();
    };
    auto ortho = [] {
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, kWidth, 0, kHeight, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    };
    static void (*setUp)() = ortho;
    const Case cases[] = {
        {"at integer positions, moved along a line",
         [] {
             setUp();
             glColor3f(0.9f, 0.3f, 0.1f);
             glRasterPos2i(3, 4);
             for (int i = 0; i < 4; ++i) glBitmap(11, 7, 0.0f, 0.0f, 12.0f, 1.0f, kGlyph);
         }},
        {"fractional positions and origins (the 1e-4 rule)",
         [] {
             setUp();
             const float xs[] = {2.0f, 2.4999f, 2.99995f, 1.99995f, 2.5f, 7.99989f};
             for (int i = 0; i < 6; ++i) {
                 glRasterPos2f(xs[i], 2.0f + 6.0f * static_cast<float>(i));
                 glBitmap(11, 7, 0.5f * static_cast<float>(i % 3), -0.25f, 0.0f, 0.0f, kGlyph);
                 glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);  // and without an origin
             }
         }},
        {"cut at every edge of the window",
         [] {
             setUp();
             glRasterPos2i(0, 0);
             glBitmap(11, 7, 5.0f, 3.0f, 0.0f, 0.0f, kGlyph);
             glRasterPos2i(kWidth, kHeight);
             glBitmap(11, 7, 4.0f, 2.0f, 0.0f, 0.0f, kGlyph);
             glRasterPos2i(kWidth - 3, 10);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
         }},
        {"moved outside the window: still valid, drawing nothing",
         [] {
             setUp();
             glRasterPos2i(40, 20);
             glBitmap(0, 0, 0.0f, 0.0f, 30.0f, -50.0f, nullptr);
             glBitmap(11, 7, 0.0f, 0.0f, -40.0f, 0.0f, kGlyph);
             glBitmap(11, 7, 0.0f, -50.0f, 0.0f, 0.0f, kGlyph);
         }},
        {"unpack alignment 4 and 8",
         [] {
             setUp();
             glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
             glRasterPos2i(2, 2);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyphAligned8);
             glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
             const GLubyte four[7 * 4] = {0xF1, 0x20, 0,    0, 0x80, 0xE0, 0,    0, 0x41, 0x40, 0,    0, 0x22, 0x00, 0,
                                          0,    0x14, 0x20, 0, 0,    0x08, 0xA0, 0, 0,    0xFF, 0x60, 0, 0};
             glBitmap(11, 7, -15.0f, 0.0f, 0.0f, 0.0f, four);
         }},
        {"compiled into a list: unpacked when compiled, drawn when called",
         [] {
             setUp();
             glRasterPos2i(2, 2);
             glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
             glNewList(5, GL_COMPILE);  // nothing drawn, the raster position not moved
             glBitmap(11, 7, 0.0f, 0.0f, 12.0f, 3.0f, kGlyphAligned8);
             glBitmap(11, 7, 1.0f, 0.0f, 12.0f, 3.0f, kGlyphAligned8);
             glEndList();
             glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
             glColor3f(0.9f, 0.8f, 0.1f);
             glRasterPos2i(3, 20);
             glCallList(5);
             glCallList(5);
             glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
             glNewList(6, GL_COMPILE_AND_EXECUTE);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, -9.0f, kGlyphAligned8);
             glEndList();
             glCallList(6);
         }},
        {"colours, including conversion ties and values out of range",
         [] {
             setUp();
             const float values[] = {145.5f / 255.0f, 0.5f, 1.0f / 3.0f, 0.9f, 100.5f / 255.0f, 1.7f, -0.2f};
             for (int i = 0; i < 7; ++i) {
                 const float v = values[i];
                 glColor4f(v, 1.0f - v, v * 0.5f, 0.75f);
                 glRasterPos2i(1 + 6 * i, 5 + 4 * i);
                 glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             }
         }},
        {"depth written at the raster z and tested",
         [] {
             setUp();
             glClearDepth(0.5);
             glClear(GL_DEPTH_BUFFER_BIT);
             glEnable(GL_DEPTH_TEST);
             glDepthFunc(GL_LESS);
             glColor3f(0.2f, 0.8f, 0.3f);
             const float zs[] = {0.3f, -0.123456f, 0.777777f, 0.1f, 0.5f, -0.9f, 0.0f, 0.2f};
             for (int i = 0; i < 8; ++i) {
                 glRasterPos3f(2.0f + 5.0f * static_cast<float>(i), 3.0f + 3.0f * static_cast<float>(i), zs[i]);
                 glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             }
             glDepthMask(GL_FALSE);
             glColor3f(1.0f, 0.0f, 1.0f);
             glRasterPos3f(4.0f, 5.0f, 0.05f);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
         }},
        {"between triangles: drawn in call order",
         [] {
             setUp();
             glEnable(GL_DEPTH_TEST);
             glClear(GL_DEPTH_BUFFER_BIT);
             glColor3f(0.0f, 0.0f, 1.0f);
             glRectf(4.0f, 4.0f, 30.0f, 20.0f);
             glColor3f(1.0f, 1.0f, 0.0f);
             glRasterPos3f(6.0f, 6.0f, -0.5f);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             glColor3f(0.0f, 1.0f, 0.0f);
             glBegin(GL_TRIANGLES);
             glVertex3f(5.0f, 5.0f, -0.2f);
             glVertex3f(25.0f, 8.0f, -0.2f);
             glVertex3f(10.0f, 18.0f, -0.2f);
             glEnd();
         }},
        {"a bitmap too big to cache is drawn before the cached ones",
         [] {
             setUp();
             static GLubyte tall[36];
             for (int i = 0; i < 36; ++i) tall[i] = static_cast<GLubyte>(i % 3 == 0 ? 0xFF : 0x3C);
             glColor3f(1.0f, 0.5f, 0.0f);
             glRasterPos2i(4, 2);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             glColor3f(0.0f, 0.5f, 1.0f);
             glRasterPos2i(6, 1);
             glBitmap(8, 36, 0.0f, 0.0f, 0.0f, 0.0f, tall);
         }},
        {"the cache ends at 512 x 32 pixels and at a new colour",
         [] {
             setUp();
             glRasterPos2i(-500, 30);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             glRasterPos2i(3, 20);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             glRasterPos2i(5, 2);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
             glColor3f(0.4f, 0.4f, 1.0f);
             glRasterPos2i(8, 4);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
         }},
        {"perspective raster position",
         [] {
             perspectiveView();
             glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
             glRasterPos3f(-0.2f, 0.1f, 0.3f);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
         }},
        {"invalid raster position: no pixels, no move",
         [] {
             setUp();
             glRasterPos2f(-3.0f, 5.0f);
             glBitmap(11, 7, 0.0f, 0.0f, 4.0f, 4.0f, kGlyph);
         }},
        {"negative size: GL_INVALID_VALUE, no move",
         [] {
             setUp();
             glRasterPos2i(5, 5);
             glBitmap(-1, 7, 0.0f, 0.0f, 4.0f, 4.0f, kGlyph);
         }},
        {"huge moves and origins: nothing drawn (no pixels), no crash",
         [] {
             setUp();
             glRasterPos2i(5, 5);
             glBitmap(11, 7, 3.0e9f, -3.0e9f, 0.0f, 0.0f, kGlyph);
             glBitmap(0, 0, 0.0f, 0.0f, 1.0e38f, -1.0e38f, nullptr);
             glBitmap(11, 7, 0.0f, 0.0f, 1.0e38f, 0.0f, kGlyph);
             glBitmap(11, 7, 0.0f, 0.0f, 0.0f, 0.0f, kGlyph);
         }},
        {"inside glBegin/glEnd: GL_INVALID_OPERATION",
         [] {
             setUp();
             glRasterPos2i(5, 5);
             glBegin(GL_POINTS);
             glBitmap(11, 7, 0.0f, 0.0f, 4.0f, 4.0f, kGlyph);
             glRasterPos2i(9, 9);
             glEnd();
         }},
    };
    for (const Case& c : cases) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
                glClear(GL_COLOR_BUFFER_BIT);
                c.draw();
                return readFrame();
            },
            kWidth, kHeight);
        expectSame(frames, c.name);
        const auto& color = frames.mygl.color;
        int lit = 0;
        for (std::size_t i = 0; i < color.size(); i += 4) lit += color[i] != color[0] || color[i + 1] != color[1];
        if (std::string(c.name).find("no pixels") == std::string::npos &&
            std::string(c.name).find("GL_INVALID") == std::string::npos &&
            std::string(c.name).find("nothing") == std::string::npos) {
            EXPECT_GT(lit, 0) << c.name << ": the case must draw something to test anything";
        }
    }
}

// With lighting on, the raster colour is lit like a vertex. The reference runs its vertex program
// for the raster position in another executor, so the colour may differ in its last bit (measured:
// 3e-8); the bytes a bitmap draws with it are the same.
TEST(RasterPos, LitColorAsTheReference) {
    constexpr int kSize = 24;
    const auto results = onBothBackends<std::vector<float>>(
        [] {
            std::vector<float> out;
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            const GLfloat position[] = {1, 2, 3, 0}, specular[] = {0.6f, 0.5f, 0.4f, 1},
                          diffuse[] = {0.3f, 0.9f, 0.2f, 0.7f};
            glLightfv(GL_LIGHT0, GL_POSITION, position);
            glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
            glMaterialf(GL_FRONT, GL_SHININESS, 20);
            glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
            glNormal3f(0.2f, 0.5f, 0.8f);
            glClear(GL_COLOR_BUFFER_BIT);
            GLubyte bits[16];  // 8 x 4 bits, rows of 4 bytes under the default unpack alignment
            std::fill(std::begin(bits), std::end(bits), GLubyte{0xff});
            for (int i = 0; i < 2; ++i) {
                if (i == 1) glEnable(GL_COLOR_MATERIAL), glColor4f(2.0f, -1.0f, 0.5f, 0.3f);
                glRasterPos3f(-0.5f + 0.6f * static_cast<float>(i), 0.2f, 0.3f);
                GLfloat c[4];
                glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
                out.insert(out.end(), c, c + 4);
                glBitmap(8, 4, 0, 0, 0, 0, bits);
            }
            std::vector<GLubyte> pixels(kSize * kSize * 4);
            glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
            out.insert(out.end(), pixels.begin(), pixels.end());
            return out;
        },
        kSize, kSize);
    ASSERT_EQ(results.mygl.size(), results.osmesa.size());
    for (std::size_t i = 0; i < 8; ++i) EXPECT_NEAR(results.mygl[i], results.osmesa[i], 1e-7f) << "raster colour " << i;
    int lit = 0;
    for (std::size_t i = 8; i < results.mygl.size(); ++i) {
        EXPECT_EQ(results.mygl[i], results.osmesa[i]) << "pixel byte " << i - 8;
        lit += results.mygl[i] != 0.0f;
    }
    EXPECT_GT(lit, 32);  // the bitmaps were drawn
}
