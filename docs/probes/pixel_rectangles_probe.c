/* The reference's pixel-rectangle rules (docs/reference-rules.md, "Pixel rectangles"), measured on
 * OSMesa: glReadPixels' conversions, its depth packing, the transfer path, and the colour map
 * lookup of glDrawPixels. Each check prints the number of values that break the stated rule
 * (0 everywhere on Debian 12's Mesa 22.3).
 * Build: gcc pixel_rectangles_probe.c $(pkg-config --cflags --libs osmesa) -lm */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void report(const char* rule, int broken) { printf("%-72s broken by %d\n", rule, broken); }

int main(void) {
    unsigned char* buffer = malloc(256 * 4 * 4);
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, 256, 4);
    /* A row with every byte value in red and a luminance sum below 1 in green/blue. */
    unsigned char image[256 * 4];
    for (int i = 0; i < 256; i++) {
        image[4 * i] = (unsigned char)i;
        image[4 * i + 1] = (unsigned char)(i / 3);
        image[4 * i + 2] = (unsigned char)(i - 2 * (i / 3) - i / 3 > 0 ? i / 4 : 0);
        image[4 * i + 3] = (unsigned char)(255 - i);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2f(-1, -1);
    glDrawPixels(256, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);

    signed char b[256];
    short s[256];
    int in[256];
    unsigned ui[256];
    unsigned short us[256];
    float f[256];
    int broken[8] = {0};
    glReadPixels(0, 0, 256, 1, GL_RED, GL_BYTE, b);
    glReadPixels(0, 0, 256, 1, GL_RED, GL_SHORT, s);
    glReadPixels(0, 0, 256, 1, GL_RED, GL_INT, in);
    glReadPixels(0, 0, 256, 1, GL_RED, GL_UNSIGNED_INT, ui);
    glReadPixels(0, 0, 256, 1, GL_RED, GL_UNSIGNED_SHORT, us);
    glReadPixels(0, 0, 256, 1, GL_RED, GL_FLOAT, f);
    for (long x = 0; x < 256; x++) {
        broken[0] += b[x] != (signed char)((x * 127 + 127) / 255);
        broken[1] += s[x] != (short)((x * 32767 + 127) / 255);
        broken[2] += in[x] != (int)((x * 2147483647L + 127) / 255);
        broken[3] += ui[x] != (unsigned)(x * 16843009u);
        broken[4] += us[x] != (unsigned short)(x * 257);
        broken[5] += f[x] != (float)x * (1.0f / 255.0f);
    }
    report("colour bytes to snorm/unorm: (x * max + 127) / 255 in integers", broken[0] + broken[1] + broken[2]);
    report("colour bytes to unsigned short/int: x * 257, x * 16843009", broken[3] + broken[4]);
    report("colour bytes to float: x * (1 / 255.0f)", broken[5]);

    float lum[256];
    int lumInt[256];
    unsigned lumUint[256];
    unsigned char lumByte[256];
    glReadPixels(0, 0, 256, 1, GL_LUMINANCE, GL_FLOAT, lum);
    glReadPixels(0, 0, 256, 1, GL_LUMINANCE, GL_INT, lumInt);
    glReadPixels(0, 0, 256, 1, GL_LUMINANCE, GL_UNSIGNED_INT, lumUint);
    glReadPixels(0, 0, 256, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, lumByte);
    int lumBroken = 0, lumWrap = 0;
    for (int x = 0; x < 256; x++) {
        const unsigned char* p = image + 4 * x;
        const float l = fminf(p[0] * (1.0f / 255) + p[1] * (1.0f / 255) + p[2] * (1.0f / 255), 1.0f);
        lumBroken += lum[x] != l || lumByte[x] != (unsigned char)lrintf(l * 255.0f);
        lumBroken += lumInt[x] != (int)llrintf(l * 2147483647.0f) || lumUint[x] != (unsigned)llrintf(l * 4294967295.0f);
        if (l == 1.0f) lumWrap += lumInt[x] != (int)0x80000000u || lumUint[x] != 0;
    }
    report("luminance: sum of x * (1/255) clamped to 1, then v * max in float, rounded", lumBroken);
    report("luminance 1 as INT reads INT_MIN, as UNSIGNED_INT 0 (wraps)", lumWrap);

    /* Depth packing, over 2001 clear depths. */
    glEnable(GL_DEPTH_TEST);
    int depthBroken[4] = {0};
    for (int k = 0; k <= 2000; k++) {
        glClearDepth(k / 2000.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        unsigned u, swapped;
        float z;
        unsigned char ub;
        signed char sb;
        short ss;
        unsigned short uss;
        int si;
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &u);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, &ub);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_BYTE, &sb);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_SHORT, &ss);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &uss);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_INT, &si);
        glPixelStorei(GL_PACK_SWAP_BYTES, 1);
        glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &swapped);
        glPixelStorei(GL_PACK_SWAP_BYTES, 0);
        const unsigned z24 = u >> 8;
        depthBroken[0] += u != ((z24 << 8) | (z24 >> 16)) || z != (float)z24 / 16777215.0f;
        depthBroken[1] += ub != (unsigned char)(int)(z * 255.0f) || sb != (signed char)(((int)(z * 255.0f) - 1) / 2) ||
                          ss != (short)(((int)(z * 65535.0f) - 1) / 2);
        depthBroken[2] += uss != (unsigned short)lrintf(z * 65535.0f) || si != (int)(2147483647.0 * z);
        depthBroken[3] += __builtin_bswap32(swapped) != (unsigned)(z * 4294967295.0);
    }
    report("depth: UNSIGNED_INT replicates the 24 bits, FLOAT is z24 / 16777215.0f", depthBroken[0]);
    report("depth: (U)BYTE/SHORT truncate ((trunc(z * 2^n - 1) - 1) / 2 if signed)", depthBroken[1]);
    report("depth: UNSIGNED_SHORT rounds, INT truncates 2147483647.0 * z", depthBroken[2]);
    report("depth: UNSIGNED_INT with swapped bytes is trunc(z * 4294967295.0)", depthBroken[3]);

    /* The transfer path: no clamp but the type's. */
    glClearColor(0.2f, 0.6f, 1.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glPixelTransferf(GL_RED_BIAS, -0.3f);
    glPixelTransferf(GL_GREEN_SCALE, 2.0f);
    float rgba[4];
    signed char rgbaByte[4];
    float la[2];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, rgba);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BYTE, rgbaByte);
    glReadPixels(0, 0, 1, 1, GL_LUMINANCE_ALPHA, GL_FLOAT, la);
    report("transfer: FLOAT keeps -0.1 and 1.2, BYTE gives -13 and 127",
           (rgba[0] > -0.09f || rgba[1] < 1.19f) + (rgbaByte[0] != -13) + (rgbaByte[1] != 127));
    report("transfer: luminance sums components clamped to [0, 1], clamps to 1", la[0] != 1.0f);
    glPixelTransferf(GL_RED_BIAS, 0.0f);
    glPixelTransferf(GL_GREEN_SCALE, 1.0f);

    /* glDrawPixels with GL_MAP_COLOR: blue and alpha come from the image at (b, a). */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    unsigned char row[16 * 4];
    for (int i = 0; i < 16; i++) {
        row[4 * i] = (unsigned char)(i * 17), row[4 * i + 1] = (unsigned char)(255 - i * 17);
        row[4 * i + 2] = (unsigned char)(i * 5), row[4 * i + 3] = 200;
    }
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glDrawPixels(16, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    unsigned char out[16 * 4];
    glReadPixels(0, 0, 16, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
    int mapBroken = 0;
    for (int i = 0; i < 16; i++) {
        const int texel = (int)floorf(row[4 * i + 2] * (1.0f / 255.0f) * 16.0f);
        mapBroken += out[4 * i + 2] != row[4 * texel] || out[4 * i + 3] != row[4 * texel + 1];
    }
    report("MAP_COLOR draws: blue/alpha are the red/green of the image texel at (b * w, a * h)", mapBroken);
    OSMesaDestroyContext(context);
    free(buffer);
    return 0;
}
