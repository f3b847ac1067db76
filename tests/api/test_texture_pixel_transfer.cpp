// Pixel transfer on texture images (GL 1.1, 3.8: glTexImage, glTexSubImage, glCopyTexImage and
// glCopyTexSubImage take their pixels through the same transfer as glDrawPixels): scale and
// bias, the GL_MAP_COLOR maps, and colour-index images (index shift and offset, then the
// I_TO_R/G/B/A maps). Each texture is read back with glGetTexImage and drawn, on MyGL and on
// OSMesa running the same calls.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cmath>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::firstDifference;
using testing_support::onBothBackends;

namespace {

constexpr int kSize = 8;  // the framebuffer the textured quad fills

// `bytes` bytes of a fixed pattern (every byte value shows up).
std::vector<GLubyte> patternBytes(std::size_t bytes, unsigned seed) {
    std::vector<GLubyte> data(bytes);
    std::uint32_t h = seed * 2654435761u + 12345u;
    for (auto& b : data) {
        h = h * 1664525u + 1013904223u;
        b = static_cast<GLubyte>(h >> 24);
    }
    return data;
}

// Floats for a GL_FLOAT image: colours in [-0.25, 1.25] (the transfer may bring them into
// range), or indices in [-3, 300) with fractions.
std::vector<GLubyte> floatImage(std::size_t count, bool indices, unsigned seed) {
    std::vector<GLubyte> data(count * 4);
    std::uint32_t h = seed * 2654435761u + 777u;
    for (std::size_t i = 0; i < count; ++i) {
        h = h * 1664525u + 1013904223u;
        const float unit = static_cast<float>(h >> 8) / 16777216.0f;
        // Whole indices: OSMesa truncates a float index before the shift (reference-rules.md).
        const float v = indices ? std::floor(unit * 303.0f) - 3.0f : unit * 1.5f - 0.25f;
        std::memcpy(&data[i * 4], &v, 4);
    }
    return data;
}

int typeBytes(GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
    case GL_BITMAP: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: return 2;
    default: return 4;
    }
}

int formatComponents(GLenum format) {
    switch (format) {
    case GL_RGBA: return 4;
    case GL_RGB: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 1;
    }
}

// An image of width x height for `format` and `type` (unpack alignment 1).
std::vector<GLubyte> image(int width, int height, GLenum format, GLenum type, unsigned seed) {
    const std::size_t count = static_cast<std::size_t>(width * height * formatComponents(format));
    if (type == GL_FLOAT) return floatImage(count, format == GL_COLOR_INDEX, seed);
    if (type == GL_BITMAP) return patternBytes(static_cast<std::size_t>((width + 7) / 8 * height), seed);
    return patternBytes(count * static_cast<std::size_t>(typeBytes(type)), seed);
}

// The transfer state a case sets before it defines its texture.
struct Transfer {
    GLfloat scale[4] = {1, 1, 1, 1}, bias[4] = {0, 0, 0, 0};
    bool mapColor = false;
    int mapSize = 0;  // the R_TO_R .. A_TO_A and I_TO_R .. I_TO_A maps' size (0: left as they are)
    int indexShift = 0, indexOffset = 0;
};

void setTransfer(const Transfer& t) {
    const GLenum scales[] = {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE};
    const GLenum biases[] = {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS};
    for (int i = 0; i < 4; ++i) {
        glPixelTransferf(scales[i], t.scale[i]);
        glPixelTransferf(biases[i], t.bias[i]);
    }
    glPixelTransferi(GL_MAP_COLOR, t.mapColor);
    glPixelTransferi(GL_INDEX_SHIFT, t.indexShift);
    glPixelTransferi(GL_INDEX_OFFSET, t.indexOffset);
    if (t.mapSize == 0) return;
    for (int m = 0; m < 4; ++m) {
        std::vector<GLfloat> values(static_cast<std::size_t>(t.mapSize));
        for (int i = 0; i < t.mapSize; ++i)
            values[static_cast<std::size_t>(i)] =
                static_cast<float>((i * (37 + 11 * m) + 5 * m) % (t.mapSize + 3)) / static_cast<float>(t.mapSize + 2);
        glPixelMapfv(static_cast<GLenum>(GL_PIXEL_MAP_R_TO_R + m), t.mapSize, values.data());
        glPixelMapfv(static_cast<GLenum>(GL_PIXEL_MAP_I_TO_R + m), t.mapSize, values.data());
    }
    // An I_TO_I map that would scramble indices if a texture image went through it (it must not).
    const GLfloat identityBreaker[4] = {3, 2, 1, 0};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 4, identityBreaker);
}

// glGetTexImage of the bound texture's level 0 as RGBA bytes, with the transfer back at its
// defaults (glGetTexImage takes none, but keep the reading plain), then a quad drawn with it
// (GL_REPLACE) read back; the error after every step.
void readTexture(GLenum target, int width, int height, std::vector<double>& out) {
    setTransfer(Transfer{});
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<GLubyte> texels(static_cast<std::size_t>(width * height * 4), 0x5A);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    out.push_back(glGetError());
    out.insert(out.end(), texels.begin(), texels.end());
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(target);
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 1, 0, 1, -1, 1);
    glRectf(0, 0, 1, 1);
    glDisable(target);
    std::vector<GLubyte> frame(kSize * kSize * 4);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, frame.data());
    out.insert(out.end(), frame.begin(), frame.end());
    out.push_back(glGetError());
}

struct ImageCase {
    GLint internalFormat;
    GLenum format, type;
    Transfer transfer;
    int dims = 2;
};

std::string describe(const ImageCase& c) {
    return "internal " + std::to_string(c.internalFormat) + " format " + std::to_string(c.format) + " type " +
           std::to_string(c.type) + " dims " + std::to_string(c.dims) + " map " + std::to_string(c.transfer.mapColor) +
           "/" + std::to_string(c.transfer.mapSize) + " shift " + std::to_string(c.transfer.indexShift) + " offset " +
           std::to_string(c.transfer.indexOffset) + " scale " + std::to_string(c.transfer.scale[0]) + " bias " +
           std::to_string(c.transfer.bias[0]);
}

// glTexImage of a 5 x 3 image (odd sizes: rows do not line up), then a 3 x 2 glTexSubImage
// of another image at (1, 1), both under the case's transfer (bitmaps 16 x 3 and 8 x 2).
std::vector<double> defineAndRead(const ImageCase& c) {
    std::vector<double> out;
    const GLenum target = c.dims == 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D;
    // Bitmap rows of whole bytes: OSMesa reads a bitmap index image as one run of bits (reference-rules.md).
    const bool bitmap = c.type == GL_BITMAP;
    const int width = bitmap ? 16 : 5, height = c.dims == 1 ? 1 : 3;
    const int partWidth = bitmap ? 8 : 3, partX = bitmap ? 8 : 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    setTransfer(c.transfer);
    const std::vector<GLubyte> whole = image(width, height, c.format, c.type, 1);
    const std::vector<GLubyte> part = image(partWidth, 2, c.format, c.type, 2);
    if (c.dims == 1) {
        glTexImage1D(target, 0, c.internalFormat, width, 0, c.format, c.type, whole.data());
        out.push_back(glGetError());
        glTexSubImage1D(target, 0, partX, partWidth, c.format, c.type, part.data());
    } else {
        glTexImage2D(target, 0, c.internalFormat, width, height, 0, c.format, c.type, whole.data());
        out.push_back(glGetError());
        glTexSubImage2D(target, 0, partX, 1, partWidth, 2, c.format, c.type, part.data());
    }
    out.push_back(glGetError());
    readTexture(target, width, height, out);
    return out;
}

void expectSame(const ImageCase& c) {
    const auto results = onBothBackends<std::vector<double>>([&] { return defineAndRead(c); }, kSize, kSize);
    EXPECT_EQ(firstDifference(results.mygl, results.osmesa), "") << describe(c);
    if (getenv("DUMP")) {
        for (std::size_t i = 0; i < results.mygl.size() && i < results.osmesa.size(); ++i)
            printf("%zu: %g %g%s\n", i, results.mygl[i], results.osmesa[i],
                   results.mygl[i] != results.osmesa[i] ? " *" : "");
    }
}

Transfer scaleAndBias() {
    Transfer t;
    const GLfloat scale[4] = {1.5f, -0.5f, 0.75f, 2.0f}, bias[4] = {-0.1f, 0.6f, 0.2f, -0.3f};
    std::memcpy(t.scale, scale, sizeof scale);
    std::memcpy(t.bias, bias, sizeof bias);
    return t;
}

Transfer mapped(int size, bool withScaleAndBias) {
    Transfer t = withScaleAndBias ? scaleAndBias() : Transfer{};
    t.mapColor = true;
    t.mapSize = size;
    return t;
}

const GLenum kColorTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                              GL_UNSIGNED_INT,  GL_INT,  GL_FLOAT};
const GLenum kIndexTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                              GL_UNSIGNED_INT,  GL_INT,  GL_FLOAT,          GL_BITMAP};
const GLint kInternalFormats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY, 4};

TEST(TexturePixelTransfer, ScaleAndBiasOnEveryColourFormatAndType) {
    const GLenum formats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_RED, GL_GREEN, GL_BLUE};
    for (GLenum format : formats) {
        for (GLenum type : kColorTypes) expectSame({GL_RGBA, format, type, scaleAndBias()});
    }
    for (GLint internal : kInternalFormats) expectSame({internal, GL_RGBA, GL_UNSIGNED_BYTE, scaleAndBias()});
}

TEST(TexturePixelTransfer, ColourMapsWithAndWithoutScaleAndBias) {
    for (int size : {1, 2, 3, 16, 64, 256}) {
        for (bool withScale : {false, true}) {
            expectSame({GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, mapped(size, withScale)});
            expectSame({GL_RGBA, GL_RGBA, GL_FLOAT, mapped(size, withScale)});
            expectSame({GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, mapped(size, withScale)});
            expectSame({GL_RGB, GL_RGB, GL_UNSIGNED_BYTE, mapped(size, withScale), 1});
        }
    }
}

TEST(TexturePixelTransfer, ColourIndexImagesOfEveryType) {
    for (GLenum type : kIndexTypes) {
        for (int size : {1, 4, 64, 256}) {
            Transfer t;
            t.mapSize = size;
            expectSame({GL_RGBA, GL_COLOR_INDEX, type, t});
            expectSame({GL_RGBA, GL_COLOR_INDEX, type, t, 1});
        }
    }
}

TEST(TexturePixelTransfer, ColourIndexShiftOffsetAndIgnoredColourTransfer) {
    for (GLenum type : {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_BITMAP}) {
        for (int shift : {0, 1, 3, -1, -4, 24, -24}) {  // (OSMesa shifts indices as 32-bit unsigned)
            for (int offset : {0, 5, -7, 1000}) {
                Transfer t = mapped(64, true);  // scale, bias and the colour maps do not apply to indices
                t.indexShift = shift;
                t.indexOffset = offset;
                expectSame({GL_RGBA, GL_COLOR_INDEX, type, t});
            }
        }
    }
}

TEST(TexturePixelTransfer, ColourIndexIntoEveryInternalFormat) {
    Transfer t;
    t.mapSize = 16;
    t.indexOffset = 3;
    for (GLint internal : kInternalFormats) expectSame({internal, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, t});
}

// A drawn gradient copied with glCopyTexImage1D/2D and glCopyTexSubImage1D/2D under the
// transfer. The 2D copies under a transfer are one row high: OSMesa's copy under a transfer
// (fallback_copy_texsubimage) reads its rows with a negative stride from the first, so every
// row but the rectangle's top one comes from memory before its buffer (reference-rules.md).
std::vector<double> copyAndRead(const Transfer& transfer, GLint internal) {
    std::vector<double> out;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kSize, 0, kSize, -1, 1);
    glBegin(GL_QUADS);
    glColor4f(0.0f, 0.1f, 0.9f, 0.3f);
    glVertex2i(0, 0);
    glColor4f(1.0f, 0.5f, 0.2f, 1.0f);
    glVertex2i(kSize, 0);
    glColor4f(0.3f, 1.0f, 0.0f, 0.6f);
    glVertex2i(kSize, kSize);
    glColor4f(0.7f, 0.0f, 0.5f, 0.0f);
    glVertex2i(0, kSize);
    glEnd();
    const bool plain = !transfer.mapColor && transfer.scale[0] == 1.0f && transfer.bias[0] == 0.0f;
    if (!plain) glCopyTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLenum>(internal), 1, 0, 4, 4, 0);
    setTransfer(transfer);
    if (plain) glCopyTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLenum>(internal), 1, 0, 4, 4, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 5, 5, 3, plain ? 2 : 1);
    out.push_back(glGetError());
    glCopyTexImage1D(GL_TEXTURE_1D, 0, static_cast<GLenum>(internal), 0, 3, 8, 0);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 2, 1, 6, 4);
    out.push_back(glGetError());
    readTexture(GL_TEXTURE_1D, 8, 1, out);
    readTexture(GL_TEXTURE_2D, 4, 4, out);
    return out;
}

TEST(TexturePixelTransfer, CopiesTakeTheTransfer) {
    for (const Transfer& t : {Transfer{}, scaleAndBias(), mapped(2, false), mapped(32, true), mapped(64, false)}) {
        for (GLint internal : {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_INTENSITY}) {
            const auto results =
                onBothBackends<std::vector<double>>([&] { return copyAndRead(t, internal); }, kSize, kSize);
            EXPECT_EQ(firstDifference(results.mygl, results.osmesa), "")
                << "internal " << internal << " map " << t.mapColor << "/" << t.mapSize;
        }
    }
}

// The errors of colour-index texture images (GL_BITMAP only with GL_COLOR_INDEX), and a list
// compiled with a colour-index image.
std::vector<double> indexImageErrors() {
    std::vector<double> out;
    const GLubyte data[64] = {1, 2, 3, 200, 7, 9, 11, 13};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_BITMAP, data);
    out.push_back(glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_BITMAP, data);
    out.push_back(glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, data);
    out.push_back(glGetError());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, data);
    out.push_back(glGetError());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_STENCIL_INDEX, GL_BITMAP, data);
    out.push_back(glGetError());
    Transfer t;
    t.mapSize = 8;
    t.indexShift = 1;
    setTransfer(t);
    glNewList(1, GL_COMPILE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, data);
    glEndList();
    t.indexShift = -1;  // the list keeps the unpacked indices; the transfer is the one when it runs
    t.indexOffset = 2;
    setTransfer(t);
    glCallList(1);
    out.push_back(glGetError());
    readTexture(GL_TEXTURE_2D, 4, 2, out);
    return out;
}

TEST(TexturePixelTransfer, IndexImageErrorsAndLists) {
    const auto results = onBothBackends<std::vector<double>>(indexImageErrors, kSize, kSize);
    EXPECT_EQ(firstDifference(results.mygl, results.osmesa), "");
}

}  // namespace
