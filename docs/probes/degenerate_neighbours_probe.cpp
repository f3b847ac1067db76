// Probe (fuzzer seed 156): three GL_TRIANGLES at 5x4, the first and last of zero area. OSMesa
// draws nothing; MyGL draws the middle triangle (3 px). With either zero-area triangle left
// out, OSMesa draws the 3 px too. Not traced in Mesa yet.
#include <cstdio>
#include <vector>

#include "backends.h"

void run(const char* what, bool first, bool last) {
    auto r = testing_support::onBothBackends<std::vector<GLubyte>>(
        [&] {
            glClear(GL_COLOR_BUFFER_BIT);
            glBegin(GL_TRIANGLES);
            if (first) {
                glVertex4f(0, 1, 1, 1);
                glVertex4f(1, 1, 1, 1);
                glVertex4f(1, 1, 1, 1);
            }
            glVertex4f(1, 1, 1, 1);
            glVertex4f(0, 0, 0, 1);
            glVertex4f(1, 0, 0, 1);
            if (last) {
                glVertex4f(0, 0, 1, 1);
                glVertex4f(0, 0, 0, 1);
                glVertex4f(0, 0, 1, 1);
            }
            glEnd();
            std::vector<GLubyte> c(5 * 4 * 4);
            glReadPixels(0, 0, 5, 4, GL_RGBA, GL_UNSIGNED_BYTE, c.data());
            return c;
        },
        5, 4);
    int mygl = 0, osmesa = 0;
    for (int i = 0; i < 20; ++i) mygl += r.mygl[i * 4] != 0, osmesa += r.osmesa[i * 4] != 0;
    printf("%s: mygl %d px, osmesa %d px\n", what, mygl, osmesa);
}

int main() {
    run("both zero-area triangles", true, true);
    run("only the first", true, false);
    run("only the last", false, true);
}
