// Probe: polygon stipple and smooth enables in one draw of filled and unfilled faces
// (docs/reference-rules.md, Line and polygon stipple; Smooth points and lines). A 40 x 40 frame,
// a front-facing triangle filled and a back-facing one in GL_LINE or GL_POINT mode, under a
// polygon stipple; prints the pixels where MyGL and OSMesa differ. Modes (argv[1], bits): 1 back
// faces GL_LINE, 2 back faces GL_POINT, 4 the back triangle after the front one, 8 before it,
// 16 the front one again after, 32 no front triangle, 64 GL_LINE_SMOOTH and GL_POINT_SMOOTH
// (point size 3), 128 no polygon stipple.
// Build: as textured_bitmap_probe.cpp.
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "backends.h"
int main(int argc, char** argv) {
    constexpr int W = 40, H = 40;
    const int mode = argc > 1 ? std::atoi(argv[1]) : 0;
    auto frames = testing_support::onBothBackends<testing_support::Frame>(
        [&] {
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            GLubyte d[128];
            for (int i = 0; i < 128; ++i) d[i] = (GLubyte)(i * 37 + 11);
            glPolygonStipple(d);
            if (!(mode & 128)) glEnable(GL_POLYGON_STIPPLE);
            if (mode & 1) glPolygonMode(GL_BACK, GL_LINE);
            if (mode & 64) {
                glEnable(GL_LINE_SMOOTH);
                glEnable(GL_POINT_SMOOTH);
                glPointSize(3);
            }
            if (mode & 2) glPolygonMode(GL_BACK, GL_POINT);
            glBegin(GL_TRIANGLES);
            if (mode & 8) {
                glVertex2f(-0.9f, 0.9f);
                glVertex2f(0.9f, 0.95f);
                glVertex2f(-0.5f, -0.2f);
            }  // back first
            if (!(mode & 32)) {
                glVertex2f(-0.9f, -0.9f);
                glVertex2f(0.9f, -0.8f);
                glVertex2f(0.1f, 0.9f);
            }  // front
            if (mode & 4) {
                glVertex2f(-0.9f, 0.9f);
                glVertex2f(0.9f, 0.95f);
                glVertex2f(-0.5f, -0.2f);
            }  // back
            if (mode & 16) {
                glVertex2f(-0.9f, -0.9f);
                glVertex2f(0.9f, -0.8f);
                glVertex2f(0.1f, 0.9f);
            }  // front again
            glEnd();
            return testing_support::readFrame(W, H);
        },
        W, H);
    int n = 0, shown = 0;
    for (int i = 0; i < W * H; ++i) {
        const GLubyte* a = &frames.mygl.color[4 * i];
        const GLubyte* b = &frames.osmesa.color[4 * i];
        if (a[0] != b[0]) {
            ++n;
            if (shown++ < 5) std::printf("x %d y %d mygl %d osmesa %d\n", i % W, i / W, a[0], b[0]);
        }
    }
    std::printf("mode %d: %d differ\n", mode, n);
}
