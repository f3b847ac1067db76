// Probe: the 24-bit depth of a depth clear the reference makes with a quad (here: the stencil
// cleared with it under a partial write mask) against a plain clear and a quad drawn at the
// clear's NDC z. Prints the three and round(d * 16777215).
// Build: g++ -O1 quad_depth_clear_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/q
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cmath>
#include <cstdio>
#include <vector>
int main() {
    std::vector<unsigned char> fb(4 * 4 * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, 4, 4);
    const double values[] = {0.72189858726754164, 0.17404983339026281, 0.82923528200836649, 0.25546391641457133,
                             0.84384532852119942};
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    for (double d : values) {
        GLuint z[3];
        glClearDepth(d);
        glClear(GL_DEPTH_BUFFER_BIT);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z[0]);
        glStencilMask(1);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glStencilMask(0xFF);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z[1]);
        const float ndc = static_cast<float>(d) * 2.0f - 1.0f;
        glBegin(GL_QUADS);
        glVertex3f(-1, -1, ndc), glVertex3f(1, -1, ndc), glVertex3f(1, 1, ndc), glVertex3f(-1, 1, ndc);
        glEnd();
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z[2]);
        std::printf("%.17g: clear %u, quad clear %u, drawn quad %u, round(d * 16777215) %.0f\n", d, z[0] >> 8,
                    z[1] >> 8, z[2] >> 8, std::nearbyint(d * 16777215.0));
    }
    OSMesaDestroyContext(ctx);
}
