// Probe: what OSMesa does with glBitmap and glDrawPixels under GL_TEXTURE_2D
// (docs/reference-rules.md, Textures). A 4 x 1 texture (red, green, blue, white; MAG_FILTER
// LINEAR by default) in MODULATE; the raster position (1, 1) set with the texture coordinates
// (0.6, 0.5) and the colour (0.8, 0.6, 1.0); then a 12 x 4 bitmap of set bits, or a white
// 12 x 4 glDrawPixels. Prints rows 1 to 3. Modes (argv[1], bits): 1 MIN_FILTER LINEAR, 2
// glDrawPixels instead of glBitmap, 4 glTexCoord2f(0.1, 0.5) after glRasterPos, 8 the texture
// matrix translated by 0.25 after glRasterPos, 16 a draw with texture coordinates after
// glRasterPos, 32 a 2 x 2 bitmap moving the raster position by (3, 1) first, 64 a draw with
// texture coordinates before glRasterPos, 128 texture generation on s.
// Build: g++ -std=c++20 -I tests/api -I mygl/include -I glrenderer/include -I reference/include
//   -I build/glad/include textured_bitmap_probe.cpp build/mygl/libmygl.a
//   build/glrenderer/libglrenderer.a build/reference/libmygl_reference.a build/libmygl_loader.a
//   $(pkg-config --libs osmesa) -lpng -lpthread
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "backends.h"

int main(int argc, char** argv) {
    constexpr int W = 32, H = 16;
    const int mode = argc > 1 ? std::atoi(argv[1]) : 0;
    reference::OsmesaContext context(W, H);
    context.makeCurrent();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLubyte texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (mode & 1) ? GL_LINEAR : GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    const std::vector<GLubyte> ones(4 * 16 * 16, 0xFF);
    glColor4f(0.8f, 0.6f, 1.0f, 1.0f);
    if (mode & 64) {  // a draw with texture coordinates before the raster position
        glBegin(GL_TRIANGLES);
        glTexCoord2f(0.3f, 0.5f);
        glVertex2f(-5, -5);
        glVertex2f(-4, -5);
        glVertex2f(-4, -4);
        glEnd();
    }
    glColor4f(0.8f, 0.6f, 1.0f, 1.0f);
    glTexCoord2f(0.6f, 0.5f);
    glRasterPos2i(1, 1);
    if (mode & 4) glTexCoord2f(0.1f, 0.5f);
    if (mode & 8) {
        glMatrixMode(GL_TEXTURE);
        glTranslatef(0.25f, 0, 0);
        glMatrixMode(GL_MODELVIEW);
    }
    if (mode & 16) {  // a draw whose vertex format has texture coordinates, before the bitmap
        glBegin(GL_TRIANGLES);
        glTexCoord2f(0.6f, 0.5f);
        glVertex2f(-5, -5);
        glVertex2f(-4, -5);
        glVertex2f(-4, -4);
        glEnd();
    }
    if (mode & 32) {  // a second bitmap first, moving the raster position by 3, 1
        glBitmap(2, 2, 0, 0, 3, 1, ones.data());
    }
    if (mode & 128) glEnable(GL_TEXTURE_GEN_S);  // texture generation (eye linear) on s
    if (mode & 2) {
        glDrawPixels(12, 4, GL_RGBA, GL_UNSIGNED_BYTE, ones.data());
    } else {
        glBitmap(12, 4, 0, 0, 0, 0, ones.data());
    }
    const testing_support::Frame frame = testing_support::readFrame(W, H);
    for (int y = 1; y <= 3; ++y) {
        for (int x = 0; x < 18; ++x) {
            const GLubyte* p = &frame.color[static_cast<std::size_t>(4 * (y * W + x))];
            std::printf("%02x%02x%02x ", p[0], p[1], p[2]);
        }
        std::printf("\n");
    }
    return 0;
}
