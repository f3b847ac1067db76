// Probe (fuzzer seed 47): a stippled GL_LINES segment, then a filled triangle, then a stippled
// line strip whose first segment the user clip plane removes (so the strip continues the
// counter of the draw before, docs/reference-rules.md). OSMesa draws the strip's first pixel
// (13, 8) when the triangle needed clipping (one vertex at z = -2): its draw then runs the
// draw module's pipeline, whose stipple stage zeroes the counter at every triangle it sees
// (draw_pipe_stipple.c stipple_reset_tri). MyGL's counter only restarts for unfilled draws.
#include <cstdio>
#include <vector>

#include "backends.h"

void run(const char* what, bool triangleClipped) {
    auto r = testing_support::onBothBackends<std::vector<GLubyte>>(
        [&] {
            glClear(GL_COLOR_BUFFER_BIT);
            glRotated(118.0, 0.0, 0.0, -0.83368165358108803);
            glRotated(-153.0, -0.17066762946517477, 0.89937473922915845, -0.81539410121150269);
            glPushMatrix();
            glLoadIdentity();
            glLineStipple(1, 1);
            glEnable(GL_LINE_STIPPLE);
            const GLdouble plane[] = {-0.79336897691713304, 0.80224148028908449, 0.0, 0.28519395807586867};
            glClipPlane(GL_CLIP_PLANE4, plane);
            glEnable(GL_CLIP_PLANE4);
            glPopMatrix();
            glBegin(GL_LINES);
            glVertex2i(0, 1);
            glVertex2i(0, 0);
            glEnd();
            glBegin(GL_TRIANGLES);
            glVertex3f(0.5f, 0.5f, 0.0f);
            glVertex3f(0.9f, 0.5f, 0.0f);
            glVertex3f(0.5f, 0.9f, triangleClipped ? -2.0f : 0.0f);
            glEnd();
            glBegin(GL_LINE_STRIP);
            glVertex4d(0.0, 0.0, -0.82975238871032408, 0.0);
            glVertex4d(0.0, 0.0, -0.46261969609327419, 1.0);
            glVertex4d(1.0, 1.0, 0.0, 1.0);
            glEnd();
            std::vector<GLubyte> c(18 * 14 * 4);
            glReadPixels(0, 0, 18, 14, GL_RGBA, GL_UNSIGNED_BYTE, c.data());
            return c;
        },
        18, 14);
    const std::size_t at = (8 * 18 + 13) * 4;
    printf("%s: pixel (13, 8) mygl %d osmesa %d\n", what, r.mygl[at], r.osmesa[at]);
}

int main() {
    run("triangle inside", false);
    run("triangle clipped", true);
}
