// Probe: does GL_POLYGON_OFFSET_POINT or GL_POLYGON_OFFSET_LINE offset a filled triangle?
// The spec: only GL_POLYGON_OFFSET_FILL does. OSMesa (llvmpipe) offsets it for any of the three
// (mode 1 and 2 differ from MyGL by the one unit of glPolygonOffset(0, 1); fuzzer seeds 87, 110, 321).
#include "backends.h"
#include <cstdio>
#include <vector>
using testing_support::onBothBackends;
int main() {
    for (int mode = 0; mode < 4; ++mode) {
        auto r = onBothBackends<std::vector<GLuint>>(
            [mode] {
                glClearDepth(1);
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                glPolygonOffset(0.0f, 1.0f);
                if (mode == 1) glEnable(GL_POLYGON_OFFSET_POINT);
                if (mode == 2) glEnable(GL_POLYGON_OFFSET_LINE);
                if (mode == 3) glEnable(GL_POLYGON_OFFSET_FILL);
                glEnable(GL_DEPTH_TEST);
                glBegin(GL_TRIANGLES);
                glVertex3f(0, 0, 0);
                glVertex3f(0, 1, 0);
                glVertex3f(1, 0, 0);
                glEnd();
                std::vector<GLuint> z(15 * 14);
                glReadPixels(0, 0, 15, 14, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z.data());
                return z;
            },
            15, 14);
        GLuint a = 0, b = 0;
        for (size_t i = 0; i < r.mygl.size(); ++i)
            if (r.mygl[i] != 0xFFFFFFFFu) {
                a = r.mygl[i] >> 8;
                b = r.osmesa[i] >> 8;
                break;
            }
        int d = 0;
        for (size_t i = 0; i < r.mygl.size(); ++i) d += r.mygl[i] != r.osmesa[i];
        printf("mode %d: %d differ, first covered mygl %u osmesa %u\n", mode, d, a, b);
    }
}
