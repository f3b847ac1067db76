// Probe: glDrawBuffer in the single-buffered OSMesa context: GL_DOUBLEBUFFER, and where a clear
// lands with each draw buffer (front, back, none, front-and-back, left...).
// Build: g++ -O1 draw_buffer_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/draw_buffer_probe
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <vector>
int main() {
    std::vector<unsigned char> fb(16 * 16 * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, 16, 16);
    GLint i;
    glGetIntegerv(GL_DOUBLEBUFFER, &i);
    std::printf("DOUBLEBUFFER %d\n", i);
    const GLenum bufs[] = {GL_FRONT, GL_BACK, GL_NONE, GL_FRONT_AND_BACK, GL_LEFT, GL_FRONT_LEFT, GL_BACK_LEFT};
    int k = 1;
    for (GLenum b : bufs) {
        glDrawBuffer(b);
        glClearColor(k * 0.1f, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        std::printf("draw 0x%x: clear %d -> user %d\n", b, (int)(k * 0.1f * 255 + 0.5f), fb[0]);
        unsigned char px[4];
        glReadBuffer(GL_FRONT);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        unsigned char pb[4];
        glReadBuffer(GL_BACK);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pb);
        std::printf("   read front %d back %d err 0x%x\n", px[0], pb[0], glGetError());
        ++k;
    }
    OSMesaDestroyContext(ctx);
}
