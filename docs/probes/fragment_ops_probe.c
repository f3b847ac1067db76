/* Probes llvmpipe's per-fragment arithmetic on an RGBA8 OSMesa buffer with 8 stencil bits:
 * alpha test precision, blending in unorm8, SRC_ALPHA_SATURATE, dithering.
 * cc fragment_ops_probe.c $(pkg-config --cflags --libs osmesa) -o probe && ./probe */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned char buf[4 * 4 * 4];

static unsigned fragmentByte(float v) { /* llvmpipe's float -> unorm8 (clamped) */
    union {
        float f;
        unsigned u;
    } b;
    if (v < 0) v = 0;
    if (v > 1) v = 1;
    b.f = v * (255.0f / 256.0f) + 32768.0f;
    return b.u & 0xFF;
}
static unsigned mul8(unsigned a, unsigned b) {
    unsigned t = a * b;
    return (t + (t >> 8) + 0x80) >> 8;
}

static void quad(float r, float g, float b, float a) {
    glColor4f(r, g, b, a);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
    glFinish();
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 4, 4);
    GLint bits;
    glGetIntegerv(GL_STENCIL_BITS, &bits);
    printf("stencil bits %d\n", bits);
    /* Alpha test: alpha 0.5 and ref 0.501 are both byte 128: LESS passes only if compared in float. */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_LESS, 0.501f);
    quad(1, 1, 1, 0.5f);
    printf("alpha 0.5 < ref 0.501: %s (float compare passes, unorm8 fails)\n", buf[0] ? "drawn" : "not drawn");
    glClear(GL_COLOR_BUFFER_BIT);
    glAlphaFunc(GL_EQUAL, 0.5f);
    quad(1, 1, 1, 0.501f);
    printf("alpha 0.501 == ref 0.5: %s (both byte 128)\n", buf[0] ? "drawn" : "not drawn");
    glDisable(GL_ALPHA_TEST);
    /* Blending: every src/dst byte pair through SRC_ALPHA, ONE_MINUS_SRC_ALPHA. */
    int mismatches = 0, tried = 0;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int s = 0; s < 256; s += 5)
        for (int a = 0; a < 256; a += 3)
            for (int d = 0; d < 256; d += 17) {
                glDisable(GL_BLEND);
                glClearColor(d / 255.0f, 0, 0, 0);
                glClear(GL_COLOR_BUFFER_BIT);
                glEnable(GL_BLEND);
                quad(s / 255.0f, 0, 0, a / 255.0f);
                unsigned sb = fragmentByte(s / 255.0f), ab = fragmentByte(a / 255.0f);
                unsigned expect = mul8(sb, ab) + mul8(d, 255 - ab);
                if (expect > 255) expect = 255;
                ++tried;
                if (buf[0] != expect) {
                    if (mismatches++ < 5) printf("  s %u a %u d %d: got %u want %u\n", sb, ab, d, buf[0], expect);
                }
            }
    printf("SRC_ALPHA/ONE_MINUS_SRC_ALPHA: %d of %d differ from mul8 + saturating add\n", mismatches, tried);
    /* ONE, ONE saturates. */
    glBlendFunc(GL_ONE, GL_ONE);
    glDisable(GL_BLEND);
    glClearColor(0.8f, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    quad(0.5f, 0, 0, 1);
    printf("ONE,ONE 204+128: %u\n", buf[0]);
    /* SRC_ALPHA_SATURATE: f = min(As, 1 - Ad) on RGB, 1 on alpha. */
    glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ZERO);
    glDisable(GL_BLEND);
    glClearColor(0, 0, 0, 0.25f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    quad(1, 1, 1, 0.9f);
    printf("SRC_ALPHA_SATURATE src 255 As 230 Ad 64: rgb %u alpha %u (min(230, 191) = %u)\n", buf[0], buf[3],
           mul8(255, 191));
    glDisable(GL_BLEND);
    /* Dithering is on by default: a colour between two bytes stays one byte everywhere? */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0.5f, 0.5f, 0.5f, 0.5f);
    int same = 1;
    for (int i = 0; i < 16; ++i) same &= buf[4 * i] == buf[0];
    printf("GL_DITHER on: %s\n", same ? "no dithering (every pixel one byte)" : "dithered");
    OSMesaDestroyContext(ctx);
    return 0;
}
