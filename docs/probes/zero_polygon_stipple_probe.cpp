// Probe: an all-zero polygon stipple pattern. GL discards every fragment of a stippled polygon;
// OSMesa draws them all when no draw has validated another pattern since the context was made
// (Mesa's state tracker sends a pattern to the driver only when it differs from its last one,
// whose copy starts all zero), and none after such a draw.
// Build: g++ -O1 zero_polygon_stipple_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/z
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <vector>
int main() {
    for (const bool drawFirst : {false, true}) {
        std::vector<unsigned char> fb(8 * 8 * 4);
        OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
        OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, 8, 8);
        glClear(GL_COLOR_BUFFER_BIT);
        if (drawFirst) glRectf(-1, -1, -0.75f, -0.75f);  // one pixel, with the default (all-ones) pattern
        const GLubyte zeros[128] = {};
        glPolygonStipple(zeros);
        glEnable(GL_POLYGON_STIPPLE);
        glRectf(-1, -1, 1, 1);
        glFinish();
        int drawn = 0;
        for (std::size_t i = 0; i < fb.size(); i += 4) drawn += fb[i + 3] != 0;
        std::printf("%s: %d of 64 pixels drawn (GL: %d)\n", drawFirst ? "after a draw" : "first draw", drawn,
                    drawFirst ? 1 : 0);
        OSMesaDestroyContext(ctx);
    }
}
