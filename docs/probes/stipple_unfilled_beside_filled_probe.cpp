// Probe: GL_POLYGON_STIPPLE with faces drawn as points. A draw of one filled front face beside a
// back face drawn as GL_POINT: OSMesa stipples the back face's points too (the spec stipples only
// filled polygons); a draw of the back face alone is not stippled. Prints the 8x8 frame (only
// columns x = 0 mod 32 pass the stipple) and the lit pixel counts.
// Build: g++ -O1 stipple_unfilled_beside_filled_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/s
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <cstring>
#include <vector>
int main() {
    const int W = 8, H = 8;
    std::vector<unsigned char> fb(W * H * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, W, H);
    GLubyte pattern[128];
    std::memset(pattern, 0, sizeof pattern);
    for (int row = 0; row < 32; ++row) pattern[row * 4] = 0x80;  // only x = 0 (mod 32) passes
    glPolygonStipple(pattern);
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonMode(GL_FRONT, GL_FILL);
    glPolygonMode(GL_BACK, GL_POINT);
    for (int order = 0; order < 2; ++order) {
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        if (order == 0) {
            glVertex2f(-1.0f, -1.0f);
            glVertex2f(-0.5f, -1.0f);
            glVertex2f(-1.0f, 1.0f);
        }  // front, left columns
        glVertex2f(0.3125f, -0.6875f);
        glVertex2f(0.5625f, 0.5625f);
        glVertex2f(0.8125f, -0.6875f);  // back: points at pixel centres x 5,6,7
        if (order == 1) {
            glVertex2f(-1.0f, -1.0f);
            glVertex2f(-0.5f, -1.0f);
            glVertex2f(-1.0f, 1.0f);
        }
        glEnd();
        glFinish();
        std::printf("order %d:\n", order);
        for (int y = H - 1; y >= 0; --y) {
            for (int x = 0; x < W; ++x) std::putchar(fb[4 * (y * W + x)] ? '#' : '.');
            std::putchar('\n');
        }
    }
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);  // the back face alone: its three points are not stippled
    glVertex2f(0.3125f, -0.6875f), glVertex2f(0.5625f, 0.5625f), glVertex2f(0.8125f, -0.6875f);
    glEnd();
    glFinish();
    int lit = 0;
    for (int i = 0; i < W * H; ++i) lit += fb[4 * i] != 0;
    std::printf("back face alone: %d px lit (3: not stippled)\n", lit);
}
