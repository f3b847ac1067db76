/* Probe: how llvmpipe filters two unorm8 texels under GL_LINEAR (docs/reference-rules.md,
 * Textures). A 2 x 1 texture (R = 10 and 138: a half at every odd weight) over a 256 x 1 window in REPLACE: pixel x
 * samples s = (x + 0.5) / 256, so the 8.8 fixed-point coordinate round(s * 2 * 256) - 128 takes every odd weight.
 * Counts the pixels each candidate lerp predicts exactly. Build: cc texture_lerp_probe.c $(pkg-config --cflags --libs
 * osmesa) -o probe */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>

#define W 256

int main(void) {
    static unsigned char buffer[W * 4];
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    const unsigned char texels[2][4] = {{10, 0, 0, 255}, {138, 0, 0, 255}};
    int x, pmulhrsw = 0, truncated = 0, exact = 0;
    if (!context || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, W, 1)) return 1;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
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
        const int fixed = (int)lrintf(s * 512.0f) - 128, weight = fixed & 255;
        const int i0 = (fixed >> 8) & 1, i1 = (i0 + 1) & 1;
        const int a = texels[i0][0], b = texels[i1][0];
        const int got = buffer[4 * x];
        pmulhrsw += got == a + ((weight * (b - a) + 128) >> 8);
        truncated += got == a + ((weight * (b - a)) >> 8);
        exact += got == (int)lrintf((float)a + (float)weight / 256.0f * (float)(b - a));
    }
    printf("of %d pixels: a + ((w*(b-a) + 128) >> 8): %d, a + ((w*(b-a)) >> 8): %d, float lerp rounded: %d\n", W,
           pmulhrsw, truncated, exact);
    OSMesaDestroyContext(context);
    return 0;
}
