// Probe: glCopyTexImage2D of a 4 x 4 rectangle under a pixel transfer (a green scale of 1.0001,
// which changes no byte). MyGL's texture is the rectangle; OSMesa's first row is the
// rectangle's top row and the other rows are what lies before its temporary buffer (here
// zeros): fallback_copy_texsubimage stores with unpack.Invert, a negative row stride from the
// buffer's first row (fuzzer rule copy-texture-rows-under-transfer).
#include <cstdio>
#include <vector>

#include "backends.h"
using testing_support::onBothBackends;
int main() {
    auto r = onBothBackends<std::vector<GLubyte>>(
        [] {
            glMatrixMode(GL_PROJECTION);
            glOrtho(0, 8, 0, 8, -1, 1);
            glBegin(GL_QUADS);
            glColor3f(0.0f, 0.1f, 0.9f);
            glVertex2i(0, 0);
            glColor3f(1.0f, 0.5f, 0.2f);
            glVertex2i(8, 0);
            glColor3f(0.3f, 1.0f, 0.0f);
            glVertex2i(8, 8);
            glColor3f(0.7f, 0.0f, 0.5f);
            glVertex2i(0, 8);
            glEnd();
            glPixelTransferf(GL_GREEN_SCALE, 1.0001f);
            glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 0, 4, 4, 0);
            std::vector<GLubyte> t(4 * 4 * 4);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
            return t;
        },
        8, 8);
    for (int row = 0; row < 4; ++row) {
        printf("row %d red: mygl", row);
        for (int x = 0; x < 4; ++x) printf(" %3d", r.mygl[(row * 4 + x) * 4]);
        printf("  osmesa");
        for (int x = 0; x < 4; ++x) printf(" %3d", r.osmesa[(row * 4 + x) * 4]);
        printf("\n");
    }
}
