/* Probe: how llvmpipe filters a GL_CLAMP texture under GL_LINEAR (docs/reference-rules.md,
 * Textures). A 2 x 1 texture (R = 10 and 200, G = 90 and 30) with the border colour
 * (0.3, 0.7, 0, 1) over a 256 x 1 window in REPLACE: pixel x samples s = (x + 0.5) / 256, so
 * u = s * 2 - 0.5 runs over [-0.5, 1.5] and both ends blend a texel with the border. Counts the
 * pixels (R and G) each candidate predicts exactly: the float sampler with a fused lerp, with an
 * unfused one, and the 8-bit sampler's lerp with the border as bytes.
 * Build: cc texture_clamp_probe.c $(pkg-config --cflags --libs osmesa) -lm -o probe */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define W 256

/* llvmpipe's float to unorm8 of a fragment colour: clamp, times 255/256, plus 2^15, low byte. */
static int toUnorm8(float v) {
    float biased;
    unsigned bits;
    v = v > 0.0f ? (v > 1.0f ? 1.0f : v) : 0.0f;
    biased = v * (255.0f / 256.0f) + 32768.0f;
    memcpy(&bits, &biased, 4);
    return (int)(bits & 0xFF);
}

int main(void) {
    static unsigned char buffer[W * 4];
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    const unsigned char texels[2][4] = {{10, 90, 0, 255}, {200, 30, 0, 255}};
    const float border[4] = {0.3f, 0.7f, 0.0f, 1.0f};
    int x, c, fused = 0, unfused = 0, bytes = 0;
    if (!context || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, W, 1)) return 1;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glViewport(0, 0, W, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glTexCoord2f(1, 0);
    glVertex2f(1, -1);
    glTexCoord2f(1, 1);
    glVertex2f(1, 1);
    glTexCoord2f(0, 1);
    glVertex2f(-1, 1);
    glEnd();
    glFinish();
    for (x = 0; x < W; ++x) {
        const float s = ((float)x + 0.5f) / W;
        const float u = fminf(fmaxf(s * 2.0f, 0.0f), 2.0f) - 0.5f;
        const float i = floorf(u), w = u - i;
        const int i0 = (int)i, i1 = i0 + 1;
        const int fixed = (int)lrintf(s * 512.0f) - 128, w8 = fixed & 255;
        int okFused = 1, okUnfused = 1, okBytes = 1;
        for (c = 0; c < 2; ++c) {
            const float a = i0 < 0 ? border[c] : texels[i0][c] * (1.0f / 255.0f);
            const float b = i1 > 1 ? border[c] : texels[i1][c] * (1.0f / 255.0f);
            const int a8 = i0 < 0 ? (int)lrintf(border[c] * 255.0f) : texels[i0][c];
            const int b8 = i1 > 1 ? (int)lrintf(border[c] * 255.0f) : texels[i1][c];
            const int got = buffer[4 * x + c];
            okFused &= got == toUnorm8(fmaf(w, b - a, a));
            okUnfused &= got == toUnorm8(w * (b - a) + a);
            okBytes &= got == a8 + ((w8 * (b8 - a8) + 128) >> 8);
        }
        fused += okFused, unfused += okUnfused, bytes += okBytes;
    }
    printf("of %d pixels: float, fused lerp: %d; float, unfused: %d; 8-bit lerp, border as bytes: %d\n", W, fused,
           unfused, bytes);
    OSMesaDestroyContext(context);
    return 0;
}
