// The count rules of the one GL function list (glcalls/gl11_calls.h) at work: a program whose
// pointer arguments cover every kind of rule (a constant; a function of the arguments: by
// parameter name, by type and n, by map order and stride; by the unpack modes and the image size)
// compiles them into display lists, overwrites its arrays and then calls the lists; its arrays
// are gone before the recording is replayed. MyGL draws from its lists' copies, OSMesa from the
// copies the call recorder kept: both must equal the picture the program meant, and each other.
// A count too small shows as a different picture (and as a read past the copy under
// AddressSanitizer); a call the list wrongly says runs at once instead of being compiled shows as
// state lost.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/context.h>
#include <reference/call_recorder.h>
#include <reference/compare.h>
#include <reference/osmesa_context.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>

namespace {

constexpr int kWidth = 64, kHeight = 48;

// Every array the program passes, each exactly as long as the call reads.
struct ProgramData {
    GLfloat lightPosition[4] = {1.0f, 2.0f, 3.0f, 0.0f};
    GLfloat lightDiffuse[4] = {0.9f, 0.8f, 0.3f, 1.0f};
    GLfloat modelAmbient[4] = {0.3f, 0.1f, 0.1f, 1.0f};
    GLfloat material[4] = {0.6f, 0.9f, 0.7f, 1.0f};
    GLfloat shininess[1] = {20.0f};
    GLfloat normal[3] = {0.0f, 0.0f, 1.0f};
    GLfloat litCorners[4][3] = {{-1.8f, -1.3f, 0.0f}, {-0.2f, -1.3f, 0.0f}, {-0.2f, 0.1f, 0.0f}, {-1.8f, 0.1f, 0.0f}};
    // 4 x 4 RGB texels read with a row length of 6, one skipped row and pixel, alignment 1.
    GLubyte texels[18 + 3 + 3 * 18 + 4 * 3] = {};
    GLfloat border[4] = {0.0f, 1.0f, 0.0f, 1.0f};
    GLfloat envColor[4] = {0.2f, 0.4f, 1.0f, 1.0f};
    GLfloat texCoords[4][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    GLfloat texturedCorners[4][2] = {{0.2f, -1.3f}, {1.8f, -1.3f}, {1.8f, 0.1f}, {0.2f, 0.1f}};
    GLushort names[2] = {1, 2};
    GLfloat fogColor[4] = {0.8f, 0.2f, 0.6f, 1.0f};
    GLfloat color[4] = {0.1f, 0.9f, 0.9f, 1.0f};
    GLfloat rectLow[2] = {-1.6f, 0.4f}, rectHigh[2] = {-0.4f, 1.2f};
    GLfloat matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.1f, 0.05f, 0, 1};
    GLfloat rasterPosition[3] = {0.2f, 0.4f, 0.0f};
    GLubyte bits[2 * 3] = {0xF0, 0xC0, 0x3C, 0x00, 0xFF, 0x40};  // 10 x 3, rows of 2 bytes (alignment 1)
    GLubyte pixels[3 * 2 * 4] = {255, 0,   0, 255, 0, 255, 0,   255, 0,   0, 255, 255,
                                 255, 255, 0, 255, 0, 255, 255, 255, 255, 0, 255, 255};
    GLfloat indexToRed[2] = {0.25f, 1.0f};
    GLubyte indices[4] = {0, 1, 1, 0};
    GLubyte stipple[32 * 4] = {};
    GLfloat controlPoints[4][3] = {{0.4f, 0.5f, 0.0f}, {0.8f, 1.4f, 0.0f}, {1.2f, -0.2f, 0.0f}, {1.7f, 1.1f, 0.0f}};
};

void view() {
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.0, 2.0, -1.5, 1.5, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

// Compiles three lists from `d`, then spoils `d`, then calls them.
void program(ProgramData& d) {
    view();
    const GLuint lists = glGenLists(3);
    // A call the list wrongly said runs at once would change the state now and not when the list
    // is called: the lists are compiled between a push and a pop of all state, which undoes it.
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPushMatrix();

    glNewList(lists + 1, GL_COMPILE);  // lighting: rules by parameter name
    glLightfv(GL_LIGHT0, GL_POSITION, d.lightPosition);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, d.lightDiffuse);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, d.modelAmbient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, d.material);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, d.shininess);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glBegin(GL_QUADS);
    glNormal3fv(d.normal);
    for (const auto& corner : d.litCorners) glVertex3fv(corner);
    glEnd();
    glDisable(GL_LIGHTING);
    glEndList();

    // A texture image: the rule by the unpack modes (which are not compiled: set now).
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 6);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glNewList(lists + 2, GL_COMPILE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, d.texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, d.border);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, d.envColor);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    glEnable(GL_TEXTURE_2D);
    glColor3f(1.0f, 0.6f, 0.2f);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
        glTexCoord2fv(d.texCoords[i]);
        glVertex2fv(d.texturedCorners[i]);
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEndList();
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);

    glNewList(lists, GL_COMPILE);
    glCallLists(2, GL_UNSIGNED_SHORT, d.names);  // by type and n
    glLoadMatrixf(d.matrix);                     // constants
    glFogfv(GL_FOG_COLOR, d.fogColor);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -1.0f);
    glFogf(GL_FOG_END, 1.5f);
    glEnable(GL_FOG);
    glColor4fv(d.color);
    glRectfv(d.rectLow, d.rectHigh);
    glDisable(GL_FOG);
    glRasterPos3fv(d.rasterPosition);
    glBitmap(10, 3, 0.0f, 0.0f, 12.0f, 0.0f, d.bits);         // by the unpack modes
    glDrawPixels(3, 2, GL_RGBA, GL_UNSIGNED_BYTE, d.pixels);  // same
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, d.indexToRed);       // by n
    glRasterPos2f(-0.2f, 1.2f);
    glDrawPixels(4, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, d.indices);
    glPolygonStipple(d.stipple);
    glEnable(GL_POLYGON_STIPPLE);
    glColor3f(0.9f, 0.9f, 0.9f);
    glRectf(1.0f, 0.3f, 1.9f, 1.4f);
    glDisable(GL_POLYGON_STIPPLE);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &d.controlPoints[0][0]);  // by order and stride
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(12, 0.0f, 1.0f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glEvalMesh1(GL_LINE, 0, 12);
    glDisable(GL_MAP1_VERTEX_3);
    glEndList();

    glPopMatrix();
    glPopAttrib();

    // What the lists must not depend on any more.
    std::memset(static_cast<void*>(&d), 0x7F, sizeof d);
    glListBase(lists);
    glCallList(lists);
    glFinish();
}

std::unique_ptr<ProgramData> freshData() {
    auto d = std::make_unique<ProgramData>();
    for (std::size_t i = 0; i < sizeof d->texels; ++i) d->texels[i] = static_cast<GLubyte>(i * 37 % 256);
    for (std::size_t i = 0; i < sizeof d->stipple; ++i) d->stipple[i] = static_cast<GLubyte>(i % 8 < 4 ? 0xCC : 0x33);
    return d;
}

int differentColors(const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint32_t> colors;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        std::uint32_t c;
        std::memcpy(&c, &rgba[i], 4);
        colors.push_back(c);
    }
    std::sort(colors.begin(), colors.end());
    return static_cast<int>(std::unique(colors.begin(), colors.end()) - colors.begin());
}

}  // namespace

TEST(PointerDataReplay, ListsAndTheRecorderKeepWhatEveryCountRuleKindSays) {
    // The program on OSMesa directly: the picture it means.
    reference::OsmesaContext direct(kWidth, kHeight);
    direct.makeCurrent();
    program(*freshData());
    const reference::Image meant{kWidth, kHeight, direct.readPixels()};

    reference::CallRecorder recorder;
    mygl::Context mygl(kWidth, kHeight);
    mygl.makeCurrent();
    recorder.start();
    program(*freshData());  // its data is freed before the replay
    recorder.stop();
    const reference::Image ours{kWidth, kHeight, mygl.readPixels()};

    reference::OsmesaContext replayed(kWidth, kHeight);
    replayed.makeCurrent();
    recorder.replay();
    const reference::Image theirs{kWidth, kHeight, replayed.readPixels()};

    EXPECT_EQ(reference::compareImages(theirs, meant).differing, 0) << "the recorder's copies";
    EXPECT_EQ(reference::compareImages(ours, meant).differing, 0) << "MyGL's display lists";
    EXPECT_GT(differentColors(meant.rgba), 10);  // the scene draws every part
}
