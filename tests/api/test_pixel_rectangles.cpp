// Pixel rectangles: glReadPixels in every GL 1.1 format and type under generated pack states,
// glDrawPixels in every colour format and type under generated zooms, raster positions and
// fragment states, and glCopyPixels, each compared with OSMesa running the same calls.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "backends.h"
#include "color_difference.h"

using testing_support::difference;
using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

// GL 1.2's BGR orders, which the reference accepts and the 1.1 loader does not name.
constexpr GLenum GL_BGR = 0x80E0, GL_BGRA = 0x80E1;

constexpr int kWidth = 40, kHeight = 30;

// Smooth-coloured triangles at different depths (every byte value of a channel somewhere, alpha
// too), so that every conversion meets many values.
void colorfulScene() {
    glClearColor(0.3f, 0.0f, 1.0f, 0.5f);
    glClearDepth(0.8);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 0);
    glVertex3f(-1.0f, -1.0f, -0.9f);
    glColor4f(0, 1, 0.5f, 1);
    glVertex3f(1.0f, -0.8f, 0.3f);
    glColor4f(0.2f, 0.7f, 1, 0.6f);
    glVertex3f(-0.7f, 1.0f, 0.95f);
    glColor4f(1, 1, 1, 1);
    glVertex3f(0.9f, 0.9f, -0.5f);
    glColor4f(0, 0, 0, 0.25f);
    glVertex3f(-0.2f, 0.1f, 0.6f);
    glColor4f(0.9f, 0.5f, 0.1f, 0.9f);
    glVertex3f(0.95f, -0.95f, 0.0f);
    glEnd();
}

struct PackState {
    int alignment, rowLength, skipPixels, skipRows;
    bool swapBytes;
};

void applyPack(const PackState& p) {
    glPixelStorei(GL_PACK_ALIGNMENT, p.alignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, p.rowLength);
    glPixelStorei(GL_PACK_SKIP_PIXELS, p.skipPixels);
    glPixelStorei(GL_PACK_SKIP_ROWS, p.skipRows);
    glPixelStorei(GL_PACK_SWAP_BYTES, p.swapBytes);
}

const GLenum kColorFormats[] = {GL_RGBA, GL_RGB, GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                GL_BGR,  GL_BGRA};
const GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
const PackState kPackStates[] = {
    {4, 0, 0, 0, false}, {1, 0, 0, 0, false}, {8, 45, 3, 2, false}, {2, 0, 1, 0, true}, {4, 41, 0, 3, true}};

struct Rectangle {
    int x, y, width, height;
};
// The whole window, a part inside, and parts hanging over each edge.
const Rectangle kRectangles[] = {
    {0, 0, kWidth, kHeight}, {5, 7, 13, 9}, {-3, -2, 9, 7}, {kWidth - 4, kHeight - 3, 9, 8}};

std::string describe(GLenum format, GLenum type, const PackState& p, const Rectangle& r) {
    return "format " + std::to_string(format) + " type " + std::to_string(type) + " alignment " +
           std::to_string(p.alignment) + " row length " + std::to_string(p.rowLength) + " skips " +
           std::to_string(p.skipPixels) + "," + std::to_string(p.skipRows) + (p.swapBytes ? " swapped" : "") +
           " rectangle " + std::to_string(r.x) + "," + std::to_string(r.y) + " " + std::to_string(r.width) + "x" +
           std::to_string(r.height);
}

// Every read of one format, as the bytes each backend wrote into memory filled with a marker
// (so what a read leaves alone counts too), and the error after each.
std::vector<std::uint8_t> readEverything(GLenum format) {
    std::vector<std::uint8_t> all;
    colorfulScene();
    for (GLenum type : kTypes) {
        for (const PackState& p : kPackStates) {
            applyPack(p);
            for (const Rectangle& r : kRectangles) {
                std::vector<std::uint8_t> memory(64 * 64 * 4 * 4 + 256, 0xA5);
                glReadPixels(r.x, r.y, r.width, r.height, format, type, memory.data());
                memory.push_back(static_cast<std::uint8_t>(glGetError()));
                all.insert(all.end(), memory.begin(), memory.end());
            }
        }
    }
    return all;
}

// Names the first read of `format` whose bytes differ.
void expectSameReads(GLenum format) {
    const auto bytes =
        onBothBackends<std::vector<std::uint8_t>>([format] { return readEverything(format); }, kWidth, kHeight);
    ASSERT_EQ(bytes.mygl.size(), bytes.osmesa.size());
    const std::size_t perRead = 64 * 64 * 4 * 4 + 257;
    for (std::size_t i = 0; i < bytes.mygl.size(); ++i) {
        if (bytes.mygl[i] == bytes.osmesa[i]) continue;
        const std::size_t read = i / perRead;
        const std::size_t perType = std::size(kPackStates) * std::size(kRectangles);
        const PackState& p = kPackStates[(read % perType) / std::size(kRectangles)];
        const Rectangle& r = kRectangles[read % std::size(kRectangles)];
        FAIL() << describe(format, kTypes[read / perType], p, r) << ": byte " << i % perRead << " is "
               << int{bytes.mygl[i]} << ", the reference's " << int{bytes.osmesa[i]};
    }
}

}  // namespace

TEST(PixelRectangles, ReadPixelsOfEveryColourFormatAndTypeEqualsTheReference) {
    for (GLenum format : kColorFormats) expectSameReads(format);
}

TEST(PixelRectangles, ReadPixelsOfDepthInEveryTypeEqualsTheReference) { expectSameReads(GL_DEPTH_COMPONENT); }

TEST(PixelRectangles, ReadPixelsErrorsEqualTheReference) {
    const auto errors = onBothBackends<std::vector<GLenum>>([] {
        std::vector<GLenum> e;
        std::vector<std::uint8_t> memory(4096);
        // (An unknown format: GL_INVALID_ENUM by the spec, the reference's departure is in test_errors.cpp.)
        const GLenum formats[] = {GL_RGBA, GL_LUMINANCE, GL_DEPTH_COMPONENT, GL_COLOR_INDEX, GL_STENCIL_INDEX};
        const GLenum types[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_BITMAP, 0x1234};
        for (GLenum format : formats) {
            for (GLenum type : types) {
                // (The reference prints "Unsupported format/type" per pixel for stencil bitmaps.)
                if (format == GL_STENCIL_INDEX && type == GL_BITMAP) continue;
                glReadPixels(0, 0, 2, 2, format, type, memory.data());
                e.push_back(glGetError());
                glReadPixels(0, 0, -1, 2, format, type, memory.data());
                e.push_back(glGetError());
            }
        }
        return e;
    });
    ASSERT_EQ(errors.mygl.size(), errors.osmesa.size());
    for (std::size_t i = 0; i < errors.mygl.size(); ++i) EXPECT_EQ(errors.mygl[i], errors.osmesa[i]) << "call " << i;
}

namespace {

// A test image of `format` and `type`: components spread over the type's range (negative
// values too for signed types, beyond [0, 1] for floats), unpack alignment 1.
std::vector<std::uint8_t> testImage(int width, int height, GLenum format, GLenum type) {
    int components = 4;
    if (format == GL_RGB || format == GL_BGR) components = 3;
    if (format == GL_LUMINANCE_ALPHA) components = 2;
    if (format == GL_RED || format == GL_GREEN || format == GL_BLUE || format == GL_ALPHA || format == GL_LUMINANCE)
        components = 1;
    const std::size_t count = static_cast<std::size_t>(width * height * components);
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = 0; i < count; ++i) {
        const double unit = static_cast<double>((i * 37 + i / 7 * 11) % 101) / 100.0;  // in [0, 1]
        const auto append = [&bytes](auto value) {
            const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
            bytes.insert(bytes.end(), p, p + sizeof value);
        };
        switch (type) {
        case GL_UNSIGNED_BYTE: append(static_cast<std::uint8_t>(unit * 255)); break;
        case GL_BYTE: append(static_cast<std::int8_t>(unit * 255 - 128)); break;
        case GL_UNSIGNED_SHORT: append(static_cast<std::uint16_t>(unit * 65535)); break;
        case GL_SHORT: append(static_cast<std::int16_t>(unit * 65535 - 32768)); break;
        case GL_UNSIGNED_INT: append(static_cast<std::uint32_t>(unit * 4294967295.0)); break;
        case GL_INT: append(static_cast<std::int32_t>(unit * 4294967295.0 - 2147483648.0)); break;
        default: append(static_cast<float>(unit * 1.4 - 0.2)); break;
        }
    }
    return bytes;
}

void flatView() {
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

void expectSameFrames(const testing_support::BothResults<Frame>& frames, const std::string& what) {
    const auto d = difference(frames.mygl, frames.osmesa);
    EXPECT_EQ(d.pixels, 0) << what << ": largest channel difference " << d.maxChannel;
    EXPECT_EQ(frames.mygl.depth, frames.osmesa.depth) << what;
}

}  // namespace

TEST(PixelRectangles, DrawPixelsOfEveryColourFormatAndTypeEqualsTheReference) {
    for (GLenum format : kColorFormats) {
        for (GLenum type : kTypes) {
            const auto image = testImage(9, 7, format, type);
            const auto frames = onBothBackends<Frame>(
                [&] {
                    flatView();
                    glRasterPos2i(3, 4);
                    glDrawPixels(9, 7, format, type, image.data());
                    return readFrame(kWidth, kHeight);
                },
                kWidth, kHeight);
            expectSameFrames(frames, "format " + std::to_string(format) + " type " + std::to_string(type));
        }
    }
}

TEST(PixelRectangles, ZoomedImagesCoverThePixelsTheReferenceCovers) {
    const float zooms[][2] = {{1, 1},      {2, 3},       {-1, 1},       {1, -1},        {0.5f, 0.5f},   {2.5f, 1.5f},
                              {-1.5f, -2}, {0.3f, 0.7f}, {3.7f, -0.6f}, {1.25f, 0.75f}, {-0.5f, 2.25f}, {0.1f, 5}};
    const float positions[][2] = {{10, 8},      {10.5f, 8.5f},  {10.49f, 7.51f},
                                  {0.2f, 0.7f}, {35.3f, 26.6f}, {-0.4f, 29.9f}};
    const auto image = testImage(11, 9, GL_RGBA, GL_UNSIGNED_BYTE);
    for (const auto& zoom : zooms) {
        for (const auto& position : positions) {
            const auto frames = onBothBackends<Frame>(
                [&] {
                    flatView();
                    glPixelZoom(zoom[0], zoom[1]);
                    glRasterPos2f(position[0], position[1]);
                    glDrawPixels(11, 9, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
                    return readFrame(kWidth, kHeight);
                },
                kWidth, kHeight);
            expectSameFrames(frames, "zoom " + std::to_string(zoom[0]) + "," + std::to_string(zoom[1]) + " at " +
                                         std::to_string(position[0]) + "," + std::to_string(position[1]));
        }
    }
}

TEST(PixelRectangles, ImagesAreDepthTestedAndFoggedAtTheRasterPosition) {
    // (Bytes: the reference may fog a float image's colours beyond [0, 1] unclamped, see
    // tests/conformance/expected_differences.txt.)
    const auto image = testImage(16, 12, GL_RGB, GL_UNSIGNED_BYTE);
    const GLenum funcs[] = {GL_LESS, GL_GREATER, GL_EQUAL, GL_ALWAYS};
    for (GLenum func : funcs) {
        for (int fog = 0; fog < 2; ++fog) {
            const auto frames = onBothBackends<Frame>(
                [&] {
                    flatView();
                    glEnable(GL_DEPTH_TEST);
                    glDepthFunc(GL_LESS);
                    glBegin(GL_TRIANGLES);  // a slanted triangle for the image to meet
                    glColor3f(0.8f, 0.8f, 0.1f);
                    glVertex3f(0, 0, 0.9f);
                    glVertex3f(40, 5, -0.9f);
                    glVertex3f(10, 30, 0.1f);
                    glEnd();
                    glDepthFunc(func);
                    if (fog) {
                        glEnable(GL_FOG);
                        glFogi(GL_FOG_MODE, GL_LINEAR);
                        glFogf(GL_FOG_START, -1.0f);
                        glFogf(GL_FOG_END, 2.0f);
                    }
                    glPixelZoom(1.5f, 1.5f);
                    glRasterPos3f(6, 5, 0.2f);
                    glDrawPixels(16, 12, GL_RGB, GL_UNSIGNED_BYTE, image.data());
                    return readFrame(kWidth, kHeight);
                },
                kWidth, kHeight);
            expectSameFrames(frames, "depth function " + std::to_string(func) + (fog ? " with fog" : ""));
        }
    }
}

TEST(PixelRectangles, NothingIsDrawnAtAnInvalidRasterPositionOrInSelection) {
    const auto image = testImage(4, 4, GL_RGBA, GL_UNSIGNED_BYTE);
    const auto frames = onBothBackends<Frame>(
        [&] {
            flatView();
            glRasterPos2f(-5, 3);  // outside the view volume: invalid
            glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
            glCopyPixels(0, 0, 8, 8, GL_COLOR);
            GLuint hits[16];
            glSelectBuffer(16, hits);
            glRenderMode(GL_SELECT);
            glRasterPos2f(5, 3);
            glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
            glRenderMode(GL_RENDER);
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    expectSameFrames(frames, "invalid raster position and selection");
}

TEST(PixelRectangles, CopyPixelsOfOverlappingZoomedAndClippedRectanglesEqualsTheReference) {
    const int copies[][4] = {{0, 0, 20, 15}, {5, 5, 20, 20}, {-4, -3, 12, 10}, {30, 20, 20, 20}, {2, 3, 40, 30}};
    const float targets[][4] = {
        {8, 6, 1, 1}, {3.5f, 2.5f, 1, 1}, {20, 10, -1, 2}, {1, 1, 0.5f, 1.5f}, {39, 29, -2, -0.75f}};
    for (const auto& copy : copies) {
        for (const auto& target : targets) {
            const auto frames = onBothBackends<Frame>(
                [&] {
                    flatView();
                    colorfulScene();
                    glDisable(GL_DEPTH_TEST);
                    glMatrixMode(GL_PROJECTION);
                    glLoadIdentity();
                    glOrtho(0, kWidth, 0, kHeight, -1, 1);
                    glMatrixMode(GL_MODELVIEW);
                    glLoadIdentity();
                    glRasterPos2f(target[0], target[1]);
                    glPixelZoom(target[2], target[3]);
                    glCopyPixels(copy[0], copy[1], copy[2], copy[3], GL_COLOR);
                    return readFrame(kWidth, kHeight);
                },
                kWidth, kHeight);
            expectSameFrames(frames, "copy " + std::to_string(copy[0]) + "," + std::to_string(copy[1]) + " to " +
                                         std::to_string(target[0]) + "," + std::to_string(target[1]));
        }
    }
}

TEST(PixelRectangles, DisplayListsKeepTheImageUnpackedAtCompileTime) {
    auto image = testImage(6, 5, GL_RGBA, GL_UNSIGNED_BYTE);
    const auto frames = onBothBackends<Frame>(
        [&image] {
            auto copy = image;
            flatView();
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 6);
            const GLuint list = glGenLists(1);
            glNewList(list, GL_COMPILE);
            glPixelZoom(2, 2);
            glRasterPos2i(4, 4);
            glDrawPixels(5, 5, GL_RGBA, GL_UNSIGNED_BYTE, copy.data());
            glCopyPixels(4, 4, 6, 6, GL_COLOR);
            glEndList();
            std::fill(copy.begin(), copy.end(), std::uint8_t{0});  // changed after compiling
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
            glPixelZoom(1, 1);
            glRasterPos2i(20, 2);
            glCallList(list);
            return readFrame(kWidth, kHeight);
        },
        kWidth, kHeight);
    expectSameFrames(frames, "display list");
}

TEST(PixelRectangles, DrawAndCopyErrorsAndZoomQueriesEqualTheReference) {
    const auto values = onBothBackends<std::vector<GLfloat>>([] {
        std::vector<GLfloat> v;
        const std::uint8_t pixels[64] = {};
        const GLenum formats[] = {GL_RGBA, GL_LUMINANCE, 0x1234};
        const GLenum types[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_BITMAP, 0x1234};
        for (GLenum format : formats) {
            for (GLenum type : types) {
                glDrawPixels(1, 1, format, type, pixels);
                v.push_back(static_cast<GLfloat>(glGetError()));
                glDrawPixels(-1, 1, format, type, pixels);
                v.push_back(static_cast<GLfloat>(glGetError()));
            }
        }
        const GLenum copyTypes[] = {GL_COLOR, GL_RGBA, 0x1234};
        for (GLenum type : copyTypes) {
            glCopyPixels(0, 0, 2, 2, type);
            v.push_back(static_cast<GLfloat>(glGetError()));
            glCopyPixels(0, 0, -2, 2, type);
            v.push_back(static_cast<GLfloat>(glGetError()));
        }
        glBegin(GL_POINTS);
        glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        glCopyPixels(0, 0, 1, 1, GL_COLOR);
        glPixelZoom(2, 2);
        glEnd();
        v.push_back(static_cast<GLfloat>(glGetError()));
        glPixelZoom(-2.5f, 0.25f);
        GLfloat zoom[2];
        glGetFloatv(GL_ZOOM_X, &zoom[0]);
        glGetFloatv(GL_ZOOM_Y, &zoom[1]);
        v.insert(v.end(), zoom, zoom + 2);
        return v;
    });
    EXPECT_EQ(values.mygl, values.osmesa);
}

namespace {

// Scales and biases, colour maps of several sizes and a depth transfer (`withMaps`: MAP_COLOR on).
void applyTransfer(bool withMaps) {
    glPixelTransferf(GL_RED_SCALE, 0.8f);
    glPixelTransferf(GL_GREEN_SCALE, 1.7f);
    glPixelTransferf(GL_BLUE_BIAS, 0.15f);
    glPixelTransferf(GL_ALPHA_SCALE, -0.5f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.9f);
    glPixelTransferf(GL_RED_BIAS, -0.1f);
    glPixelTransferf(GL_DEPTH_SCALE, 0.7f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.2f);
    if (!withMaps) return;
    std::vector<GLfloat> ramp(37);
    for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = static_cast<GLfloat>((i * 7) % 37) / 36.0f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 37, ramp.data());
    const GLuint green[] = {0u, 4294967295u, 1000000000u};
    glPixelMapuiv(GL_PIXEL_MAP_G_TO_G, 3, green);
    const GLushort blue[] = {65535, 0, 30000, 12345, 54321};
    glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 5, blue);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
}

}  // namespace

TEST(PixelRectangles, ReadPixelsThroughScaleBiasAndMapsEqualsTheReference) {
    for (int maps = 0; maps < 2; ++maps) {
        const auto bytes = onBothBackends<std::vector<std::uint8_t>>(
            [maps] {
                colorfulScene();
                applyTransfer(maps != 0);
                std::vector<std::uint8_t> all;
                for (GLenum format :
                     {GL_RGBA, GL_RGB, GL_GREEN, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_DEPTH_COMPONENT}) {
                    for (GLenum type : kTypes) {
                        std::vector<std::uint8_t> memory(kWidth * kHeight * 16, 0xA5);
                        glReadPixels(0, 0, kWidth, kHeight, format, type, memory.data());
                        all.insert(all.end(), memory.begin(), memory.end());
                    }
                }
                return all;
            },
            kWidth, kHeight);
        ASSERT_EQ(bytes.mygl.size(), bytes.osmesa.size());
        const auto differs = std::mismatch(bytes.mygl.begin(), bytes.mygl.end(), bytes.osmesa.begin());
        if (differs.first == bytes.mygl.end()) continue;
        const auto at = static_cast<std::size_t>(differs.first - bytes.mygl.begin());
        const std::size_t perRead = kWidth * kHeight * 16;
        ADD_FAILURE() << (maps ? "with colour maps" : "scale and bias") << ": read " << at / perRead
                      << " (format, type) byte " << at % perRead << " is " << int{*differs.first}
                      << ", the reference's " << int{*differs.second};
    }
}

TEST(PixelRectangles, DrawAndCopyPixelsThroughScaleBiasAndMapsEqualTheReference) {
    const auto image = testImage(12, 10, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int maps = 0; maps < 2; ++maps) {
        const auto frames = onBothBackends<Frame>(
            [&] {
                flatView();
                colorfulScene();
                glDisable(GL_DEPTH_TEST);
                flatView();
                applyTransfer(maps != 0);
                glRasterPos2i(2, 3);
                glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
                glPixelZoom(1.5f, 1.0f);
                glRasterPos2i(20, 12);
                glCopyPixels(0, 0, 14, 12, GL_COLOR);
                return readFrame(kWidth, kHeight);
            },
            kWidth, kHeight);
        expectSameFrames(frames, maps ? "with colour maps" : "scale and bias");
    }
}

TEST(PixelRectangles, PixelModeStateQueriesErrorsAndAttribGroupEqualTheReference) {
    const auto values = onBothBackends<std::vector<double>>([] {
        std::vector<double> v;
        const auto error = [&v] { v.push_back(static_cast<double>(glGetError())); };
        const GLenum names[] = {GL_MAP_COLOR,
                                GL_MAP_STENCIL,
                                GL_INDEX_SHIFT,
                                GL_INDEX_OFFSET,
                                GL_RED_SCALE,
                                GL_GREEN_SCALE,
                                GL_BLUE_SCALE,
                                GL_ALPHA_SCALE,
                                GL_RED_BIAS,
                                GL_GREEN_BIAS,
                                GL_BLUE_BIAS,
                                GL_ALPHA_BIAS,
                                GL_DEPTH_SCALE,
                                GL_DEPTH_BIAS,
                                GL_ZOOM_X,
                                GL_ZOOM_Y,
                                GL_MAX_PIXEL_MAP_TABLE,
                                GL_PIXEL_MAP_I_TO_I_SIZE,
                                GL_PIXEL_MAP_S_TO_S_SIZE,
                                GL_PIXEL_MAP_I_TO_R_SIZE,
                                GL_PIXEL_MAP_I_TO_A_SIZE,
                                GL_PIXEL_MAP_R_TO_R_SIZE,
                                GL_PIXEL_MAP_G_TO_G_SIZE,
                                GL_PIXEL_MAP_B_TO_B_SIZE,
                                GL_PIXEL_MAP_A_TO_A_SIZE};
        const auto queryAll = [&] {
            for (GLenum name : names) {
                GLfloat f = -7;
                GLint i = -7;
                GLboolean b = 7;
                glGetFloatv(name, &f);
                glGetIntegerv(name, &i);
                glGetBooleanv(name, &b);
                v.insert(v.end(), {f, double(i), double(b)});
            }
            error();
            const GLenum maps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_G,
                                   GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_A_TO_A};
            for (GLenum map : maps) {
                GLfloat f[256] = {};
                GLuint ui[256] = {};
                GLushort us[256] = {};
                glGetPixelMapfv(map, f);
                glGetPixelMapuiv(map, ui);
                glGetPixelMapusv(map, us);
                for (int i = 0; i < 8; ++i) v.insert(v.end(), {f[i], double(ui[i]), double(us[i])});
            }
            error();
        };
        queryAll();
        glPushAttrib(GL_PIXEL_MODE_BIT);
        glPixelTransferi(GL_INDEX_SHIFT, -3);
        glPixelTransferf(GL_INDEX_OFFSET, 2.7f);
        glPixelTransferi(GL_MAP_STENCIL, 5);
        glPixelTransferf(GL_GREEN_BIAS, -0.25f);
        glPixelZoom(-2.0f, 0.5f);
        applyTransfer(true);
        const GLfloat indexValues[] = {3.5f, -2.0f, 700.25f, 1e6f};
        glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 4, indexValues);
        glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, indexValues);
        const GLfloat colors[] = {-0.5f, 0.25f, 1.5f};
        glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 3, colors);
        const GLuint stencil[] = {9u, 4000000000u};
        glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, stencil);
        queryAll();
        // Errors: a bad parameter or map, sizes out of range, index maps not a power of two.
        glPixelTransferf(0x1234, 1.0f);
        error();
        glPixelMapfv(0x1234, 1, colors);
        error();
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, colors);
        error();
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, colors);
        error();
        glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, colors);
        error();
        glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 3, colors);
        error();
        glGetPixelMapfv(0x1234, nullptr);
        error();
        glBegin(GL_POINTS);
        glPixelTransferf(GL_RED_SCALE, 2.0f);
        glEnd();
        error();
        glPopAttrib();
        queryAll();
        return v;
    });
    ASSERT_EQ(values.mygl.size(), values.osmesa.size());
    for (std::size_t i = 0; i < values.mygl.size(); ++i) EXPECT_EQ(values.mygl[i], values.osmesa[i]) << "value " << i;
}

TEST(PixelRectangles, DrawnAndCopiedPixelsGoThroughThePerFragmentOperations) {
    const auto image = testImage(14, 11, GL_RGBA, GL_UNSIGNED_BYTE);
    enum Operation { Blend, AlphaTest, Scissor, Stencil, ColorMask, LogicOp, StencilKeep, kOperations };
    for (int operation = 0; operation < kOperations; ++operation) {
        for (float zoom : {1.0f, 1.5f}) {
            const auto frames = onBothBackends<Frame>(
                [&] {
                    flatView();
                    colorfulScene();
                    glDisable(GL_DEPTH_TEST);
                    flatView();
                    glClearStencil(0);
                    glClear(GL_STENCIL_BUFFER_BIT);
                    switch (operation) {
                    case Blend:
                        glEnable(GL_BLEND);
                        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                        break;
                    case AlphaTest:
                        glEnable(GL_ALPHA_TEST);
                        glAlphaFunc(GL_GREATER, 0.4f);
                        break;
                    case Scissor:
                        glEnable(GL_SCISSOR_TEST);
                        glScissor(5, 4, 20, 15);
                        break;
                    case Stencil:
                    case StencilKeep:
                        // A triangle marks the stencil; the images draw where it is 1 (and increment
                        // it, or keep it).
                        glEnable(GL_STENCIL_TEST);
                        glStencilFunc(GL_ALWAYS, 1, 0xFF);
                        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
                        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
                        glBegin(GL_TRIANGLES);
                        glVertex2f(0, 0);
                        glVertex2f(40, 5);
                        glVertex2f(12, 30);
                        glEnd();
                        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                        glStencilFunc(GL_EQUAL, 1, 0xFF);
                        if (operation == Stencil)
                            glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
                        else
                            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
                        break;
                    case ColorMask: glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE); break;
                    case LogicOp:
                        glEnable(GL_COLOR_LOGIC_OP);
                        glLogicOp(GL_XOR);
                        break;
                    }
                    glPixelZoom(zoom, zoom);
                    glRasterPos2i(2, 3);
                    glDrawPixels(14, 11, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
                    glRasterPos2i(22, 14);
                    glCopyPixels(0, 0, 14, 12, GL_COLOR);
                    glDisable(GL_SCISSOR_TEST);
                    glDisable(GL_STENCIL_TEST);
                    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                    return readFrame(kWidth, kHeight);
                },
                kWidth, kHeight);
            expectSameFrames(frames, "operation " + std::to_string(operation) + " zoom " + std::to_string(zoom));
        }
    }
}

TEST(PixelRectangles, FeedbackGetsDrawAndCopyPixelTokensAtValidRasterPositions) {
    const auto values = onBothBackends<std::vector<GLfloat>>(
        [] {
            flatView();
            std::vector<GLfloat> buffer(256, -1.0f);
            const GLubyte pixels[16] = {};
            const GLuint list = glGenLists(1);
            glNewList(list, GL_COMPILE);
            glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            glCopyPixels(0, 0, 3, 3, GL_COLOR);
            glEndList();
            glFeedbackBuffer(static_cast<GLsizei>(buffer.size()), GL_3D_COLOR_TEXTURE, buffer.data());
            glRenderMode(GL_FEEDBACK);
            glColor3f(0.25f, 0.5f, 0.75f);
            glBegin(GL_POINTS);
            glVertex2f(3, 4);
            glEnd();
            glRasterPos3f(5.5f, 6.25f, 0.5f);
            glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            glDrawPixels(0, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // a token all the same
            glCopyPixels(1, 2, 3, 4, GL_COLOR);
            glCallList(list);
            glDrawPixels(-1, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);  // an error: no token
            glRasterPos2f(-5, 3);                                    // invalid: no tokens
            glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            glCopyPixels(1, 2, 3, 4, GL_COLOR);
            std::vector<GLfloat> out{static_cast<GLfloat>(glRenderMode(GL_RENDER)), static_cast<GLfloat>(glGetError())};
            out.insert(out.end(), buffer.begin(), buffer.end());
            return out;
        },
        kWidth, kHeight);
    EXPECT_EQ(values.mygl, values.osmesa);
    EXPECT_GT(values.osmesa[0], 20.0f);  // the point and five raster tokens
}
