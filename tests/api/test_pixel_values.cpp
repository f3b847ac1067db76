// glDrawPixels of depth, stencil and colour-index images and glCopyPixels of depth and stencil:
// every type under depth scale and bias, index maps, zooms and fragment states, compared with
// OSMesa running the same calls (colour, depth and stencil buffers).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

constexpr int kWidth = 40, kHeight = 30;

constexpr GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT};

// Colour, depth and stencil of every pixel, after glFinish.
struct Buffers {
    std::vector<GLubyte> color;
    std::vector<GLuint> depth;
    std::vector<GLubyte> stencil;
    bool operator==(const Buffers&) const = default;
};

Buffers readBuffers() {
    const auto n = static_cast<std::size_t>(kWidth * kHeight);
    Buffers b{std::vector<GLubyte>(n * 4), std::vector<GLuint>(n), std::vector<GLubyte>(n)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
    glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b.depth.data());
    glReadPixels(0, 0, kWidth, kHeight, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b.stencil.data());
    return b;
}

// The first pixel where two reads differ, for a failure message.
std::string firstDifference(const Buffers& ours, const Buffers& theirs) {
    for (std::size_t i = 0; i < ours.depth.size(); ++i) {
        const int x = static_cast<int>(i) % kWidth, y = static_cast<int>(i) / kWidth;
        const std::string at = " at " + std::to_string(x) + "," + std::to_string(y) + ": ";
        if (std::memcmp(&ours.color[4 * i], &theirs.color[4 * i], 4) != 0) {
            return "colour" + at + std::to_string(ours.color[4 * i]) + "," + std::to_string(ours.color[4 * i + 1]) +
                   "," + std::to_string(ours.color[4 * i + 2]) + "," + std::to_string(ours.color[4 * i + 3]) + " vs " +
                   std::to_string(theirs.color[4 * i]) + "," + std::to_string(theirs.color[4 * i + 1]) + "," +
                   std::to_string(theirs.color[4 * i + 2]) + "," + std::to_string(theirs.color[4 * i + 3]);
        }
        if (ours.depth[i] != theirs.depth[i]) {
            return "depth" + at + std::to_string(ours.depth[i] >> 8) + " vs " + std::to_string(theirs.depth[i] >> 8);
        }
        if (ours.stencil[i] != theirs.stencil[i]) {
            return "stencil" + at + std::to_string(ours.stencil[i]) + " vs " + std::to_string(theirs.stencil[i]);
        }
    }
    return "";
}

void expectSameBuffers(const std::function<void()>& calls, const std::string& what) {
    const auto frames = onBothBackends<Buffers>(
        [&] {
            calls();
            return readBuffers();
        },
        kWidth, kHeight);
    EXPECT_EQ(firstDifference(frames.mygl, frames.osmesa), "") << what;
}

// A scene of depths and stencil values to draw over: cleared, then a smooth triangle in depth
// that also sets the stencil to 1 where it is drawn.
void sceneBehind() {
    testing_support::clearedOrthoView(kWidth, kHeight, {0.1f, 0.2f, 0.3f, 1.0f}, 0.6, 0x5A);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0xC3, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(2, 2, 0.9f);
    glColor3f(0, 1, 0);
    glVertex3f(38, 5, -0.9f);
    glColor3f(0, 0, 1);
    glVertex3f(20, 28, 0.1f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

// A width x height image of one component of `type`, its values spread over the type's range
// (beyond [0, 1] for floats, negative for signed types), with the extremes among them.
std::vector<std::uint8_t> valueImage(int width, int height, GLenum type) {
    const int n = width * height;
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(n) * 4);
    std::uint32_t seed = 12345u + type;
    for (int i = 0; i < n; ++i) {
        seed = seed * 1664525u + 1013904223u;
        const std::uint32_t r = seed ^ (seed >> 13);
        const bool extreme = i % 7 == 0;
        auto* p = bytes.data();
        switch (type) {
        case GL_UNSIGNED_BYTE: p[i] = static_cast<std::uint8_t>(extreme ? (i % 2 ? 255 : 0) : r); break;
        case GL_BYTE: p[i] = static_cast<std::uint8_t>(extreme ? (i % 2 ? 127 : 0x80) : r); break;
        case GL_UNSIGNED_SHORT:
        case GL_SHORT: {
            const auto v = static_cast<std::uint16_t>(extreme ? (i % 2 ? 0x7FFF : 0xFFFF) : r);
            std::memcpy(p + 2 * i, &v, 2);
            break;
        }
        case GL_UNSIGNED_INT:
        case GL_INT: {
            const std::uint32_t v = extreme ? (i % 2 ? 0x7FFFFFFFu : 0xFFFFFFFFu) : r;
            std::memcpy(p + 4 * i, &v, 4);
            break;
        }
        default: {
            const float extremes[] = {1.0f / 3.0f, -0.25f, NAN, INFINITY, -INFINITY, 1e30f};
            const float v = extreme ? extremes[(i / 7) % 6] : static_cast<float>(r % 1200) / 1000.0f;
            std::memcpy(p + 4 * i, &v, 4);
        }
        }
    }
    return bytes;
}

}  // namespace

TEST(PixelValues, DepthImagesOfEveryTypeWriteTheReferencesDepths) {
    for (GLenum type : kTypes) {
        const auto image = valueImage(13, 9, type);
        for (const GLenum func : {GL_ALWAYS, GL_LESS, GL_GEQUAL}) {
            expectSameBuffers(
                [&] {
                    sceneBehind();
                    glEnable(GL_DEPTH_TEST);
                    glDepthFunc(func);
                    glColor4f(0.2f, 0.9f, 0.4f, 0.7f);
                    glRasterPos3f(5.5f, 4.5f, 0.3f);
                    glDrawPixels(13, 9, GL_DEPTH_COMPONENT, type, image.data());
                },
                "type " + std::to_string(type) + " func " + std::to_string(func));
        }
    }
}

TEST(PixelValues, DepthScaleAndBiasApplyToEveryType) {
    const float transfers[][2] = {{0.5f, 0.25f}, {2.0f, -0.5f}, {1.0f, 0.1f}, {-1.0f, 1.0f}, {NAN, 0.0f}};
    for (GLenum type : kTypes) {
        const auto image = valueImage(11, 7, type);
        for (const auto& t : transfers) {
            expectSameBuffers(
                [&] {
                    sceneBehind();
                    glEnable(GL_DEPTH_TEST);
                    glDepthFunc(GL_ALWAYS);
                    glPixelTransferf(GL_DEPTH_SCALE, t[0]);
                    glPixelTransferf(GL_DEPTH_BIAS, t[1]);
                    glRasterPos2i(3, 2);
                    glDrawPixels(11, 7, GL_DEPTH_COMPONENT, type, image.data());
                },
                "type " + std::to_string(type) + " scale " + std::to_string(t[0]) + " bias " + std::to_string(t[1]));
        }
    }
}

TEST(PixelValues, DepthImagesGoThroughZoomsMasksAndFragmentOperations) {
    const auto image = valueImage(9, 8, GL_FLOAT);
    const float zooms[][2] = {{1, 1}, {2, 3}, {-1.5f, 1}, {0.5f, -0.5f}, {2.5f, 1.25f}};
    for (const auto& zoom : zooms) {
        for (int state = 0; state < 5; ++state) {
            expectSameBuffers(
                [&] {
                    sceneBehind();
                    glEnable(GL_DEPTH_TEST);
                    glDepthFunc(GL_LEQUAL);
                    if (state == 1) glDepthMask(GL_FALSE);
                    if (state == 2) glDisable(GL_DEPTH_TEST);
                    if (state == 3) {  // blending, fog (the depth program draws no fog), alpha test
                        glEnable(GL_BLEND);
                        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                        glEnable(GL_FOG);
                        glFogi(GL_FOG_MODE, GL_LINEAR);
                        glEnable(GL_ALPHA_TEST);
                        glAlphaFunc(GL_GREATER, 0.5f);
                    }
                    if (state == 4) {  // the stencil test and a stencil operation
                        glEnable(GL_STENCIL_TEST);
                        glStencilFunc(GL_EQUAL, 0xC3, 0xFF);
                        glStencilOp(GL_KEEP, GL_INCR, GL_INVERT);
                    }
                    glPixelZoom(zoom[0], zoom[1]);
                    glColor4f(0.9f, 0.3f, 0.6f, 0.75f);
                    glRasterPos3f(15.3f, 12.7f, 0.9f);
                    glDrawPixels(9, 8, GL_DEPTH_COMPONENT, GL_FLOAT, image.data());
                },
                "zoom " + std::to_string(zoom[0]) + "," + std::to_string(zoom[1]) + " state " + std::to_string(state));
        }
    }
}

TEST(PixelValues, StencilImagesOfEveryTypeWriteUnderTheWriteMaskAndMap) {
    std::vector<GLfloat> map(16);
    for (int i = 0; i < 16; ++i) map[static_cast<std::size_t>(i)] = static_cast<float>((i * 37 + 5) % 300);
    for (GLenum type : kTypes) {
        const auto image = valueImage(12, 9, type);
        for (int state = 0; state < 4; ++state) {
            expectSameBuffers(
                [&] {
                    sceneBehind();
                    // Depth and stencil tests that would fail: the image writes its values anyway.
                    glEnable(GL_DEPTH_TEST);
                    glDepthFunc(GL_NEVER);
                    glEnable(GL_STENCIL_TEST);
                    glStencilFunc(GL_NEVER, 0, 0xFF);
                    if (state == 1) glStencilMask(0x3C);
                    if (state == 2) {
                        glPixelTransferi(GL_INDEX_SHIFT, 2);
                        glPixelTransferi(GL_INDEX_OFFSET, 7);
                    }
                    if (state == 3) {
                        glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 16, map.data());
                        glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
                    }
                    glPixelZoom(state == 3 ? 1.5f : 1.0f, state == 3 ? -2.0f : 1.0f);
                    glRasterPos2f(6.4f, 20.5f);
                    glDrawPixels(12, 9, GL_STENCIL_INDEX, type, image.data());
                },
                "type " + std::to_string(type) + " state " + std::to_string(state));
        }
    }
}

// (GL_STENCIL_INDEX with GL_BITMAP makes the reference print "Unsupported format/type" for
// every pixel: not compared; MyGL writes the bits as 0 and 1. With GL_UNPACK_SKIP_PIXELS the
// reference's colour-index bitmaps take colours of no map entry from the second row on, varying
// from run to run: not compared.)
TEST(PixelValues, ColorIndexBitmapsReadTheirRowsAsTheReferenceDoes) {
    const std::uint8_t bits[] = {0xA5, 0x3C, 0xFF, 0x00, 0x81, 0x7E, 0x0F, 0xF0};
    const GLfloat red[2] = {0.25f, 1.0f}, alpha[2] = {1.0f, 0.5f};
    for (const int width : {13, 16}) {
        for (const bool lsbFirst : {false, true}) {
            expectSameBuffers(
                [&] {
                    sceneBehind();
                    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, red);
                    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, alpha);
                    glPixelStorei(GL_UNPACK_LSB_FIRST, lsbFirst);
                    glPixelZoom(1.5f, 2.0f);
                    glRasterPos2i(5, 5);
                    glDrawPixels(width, 4, GL_COLOR_INDEX, GL_BITMAP, bits);
                },
                "width " + std::to_string(width) + (lsbFirst ? " lsb first" : ""));
        }
    }
}

TEST(PixelValues, ScissoredStencilImagesUnderAWriteMask) {
    const auto stencil = valueImage(16, 10, GL_UNSIGNED_BYTE);
    for (const GLuint mask : {0xF0u, 0x81u}) {
        expectSameBuffers(
            [&] {
                sceneBehind();
                glEnable(GL_SCISSOR_TEST);
                glScissor(8, 6, 20, 12);
                glStencilMask(mask);
                glPixelZoom(1.5f, 1.25f);
                glRasterPos2i(4, 12);
                glDrawPixels(16, 10, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
            },
            "mask " + std::to_string(mask));
    }
}

TEST(PixelValues, ColorIndexImagesOfEveryTypeTakeTheIndexMaps) {
    std::vector<GLfloat> red(8), green(4), blue(16), alpha(2);
    for (int i = 0; i < 16; ++i) {
        if (i < 8) red[static_cast<std::size_t>(i)] = static_cast<float>(i) / 7.0f;
        if (i < 4) green[static_cast<std::size_t>(i)] = 1.0f - static_cast<float>(i) / 3.3f;
        blue[static_cast<std::size_t>(i)] = static_cast<float>((i * 5) % 16) / 15.0f;
        if (i < 2) alpha[static_cast<std::size_t>(i)] = 0.3f + 0.6f * static_cast<float>(i);
    }
    for (GLenum type : kTypes) {
        const auto image = valueImage(10, 8, type);
        for (int state = 0; state < 3; ++state) {
            expectSameBuffers(
                [&] {
                    sceneBehind();
                    if (state > 0) {
                        glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 8, red.data());
                        glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, green.data());
                        glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 16, blue.data());
                        glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, alpha.data());
                    }
                    if (state == 2) {  // shift, offset, colour scale and map: none applies to indices
                        glPixelTransferi(GL_INDEX_SHIFT, 1);
                        glPixelTransferi(GL_INDEX_OFFSET, 3);
                        glPixelTransferf(GL_RED_SCALE, 0.5f);
                        glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
                        glPixelZoom(2, -1.5f);
                    }
                    glRasterPos2f(4.5f, 18.5f);
                    glDrawPixels(10, 8, GL_COLOR_INDEX, type, image.data());
                },
                "type " + std::to_string(type) + " state " + std::to_string(state));
        }
    }
}

TEST(PixelValues, CopiesOfDepthAndStencilEqualTheReference) {
    struct Copy {
        int x, y, w, h;
        float toX, toY, zoomX, zoomY;
    };
    const Copy copies[] = {{2, 2, 12, 10, 20, 15, 1, 1},   {5, 3, 15, 12, 9, 7, 1, 1},     // apart, overlapping
                           {-4, -3, 14, 11, 22, 14, 1, 1}, {30, 20, 16, 14, 3, 4, 1, 1},   // outside the window
                           {4, 4, 10, 8, 12, 6, 2, 1.5f},  {6, 5, 9, 9, 30, 25, -1, -1}};  // zoomed
    for (const GLenum type : {GL_DEPTH, GL_STENCIL}) {
        for (const Copy& c : copies) {
            for (int state = 0; state < 3; ++state) {
                expectSameBuffers(
                    [&] {
                        sceneBehind();
                        glEnable(GL_DEPTH_TEST);
                        glDepthFunc(state == 1 ? GL_GREATER : GL_ALWAYS);
                        if (state == 2) {
                            glStencilMask(0x0F);
                            glDepthMask(GL_FALSE);
                            glEnable(GL_SCISSOR_TEST);
                            glScissor(6, 4, 25, 20);
                            glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
                            glPixelTransferi(GL_INDEX_OFFSET, 3);
                        }
                        glColor4f(0.3f, 0.8f, 0.1f, 1.0f);
                        glPixelZoom(c.zoomX, c.zoomY);
                        glRasterPos2f(c.toX, c.toY);
                        glColor4f(0.7f, 0.2f, 0.9f, 1.0f);  // copies of depth take the current colour
                        glCopyPixels(c.x, c.y, c.w, c.h, type);
                    },
                    "type " + std::to_string(type) + " from " + std::to_string(c.x) + "," + std::to_string(c.y) +
                        " zoom " + std::to_string(c.zoomX) + " state " + std::to_string(state));
            }
        }
    }
}

TEST(PixelValues, DisplayListsKeepValuesUnpackedAtCompileTimeAndTransferAtExecution) {
    const auto depths = valueImage(8, 6, GL_UNSIGNED_SHORT);
    const auto indices = valueImage(8, 6, GL_UNSIGNED_BYTE);
    const GLfloat map[4] = {0.0f, 0.4f, 0.8f, 1.0f};
    expectSameBuffers(
        [&] {
            sceneBehind();
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 8);
            const GLuint list = glGenLists(1);
            glNewList(list, GL_COMPILE);
            glRasterPos2i(3, 3);
            glDrawPixels(6, 6, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depths.data());
            glRasterPos2i(20, 3);
            glDrawPixels(6, 6, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, indices.data());
            glRasterPos2i(20, 15);
            glDrawPixels(6, 6, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices.data());
            glEndList();
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glPixelTransferf(GL_DEPTH_BIAS, 0.2f);
            glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, map);
            glCallList(list);
            glDeleteLists(list, 1);
        },
        "list");
}

TEST(PixelValues, DrawAndCopyErrorsOfValueFormatsEqualTheReference) {
    const std::uint8_t data[64] = {};
    const auto errors = onBothBackends<std::vector<GLenum>>([&] {
        std::vector<GLenum> out;
        const GLenum formats[] = {GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, GL_COLOR_INDEX};
        const GLenum types[] = {GL_BITMAP, GL_UNSIGNED_BYTE, GL_FLOAT, GL_DOUBLE, GL_RGBA};
        for (GLenum format : formats) {
            for (GLenum type : types) {
                if (format == GL_STENCIL_INDEX && type == GL_BITMAP) continue;  // see above
                glDrawPixels(2, 2, format, type, data);
                out.push_back(glGetError());
            }
        }
        for (const GLenum type : {GL_DEPTH, GL_STENCIL, GL_COLOR_INDEX, GL_DEPTH_COMPONENT}) {
            glCopyPixels(0, 0, 2, 2, type);
            out.push_back(glGetError());
        }
        glCopyPixels(0, 0, -1, 2, GL_DEPTH);
        out.push_back(glGetError());
        return out;
    });
    EXPECT_EQ(errors.mygl, errors.osmesa);
}
