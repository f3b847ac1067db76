/* The reference's rules for glDrawPixels of depth, stencil and colour-index images and
 * glCopyPixels of depth (docs/reference-rules.md, "Pixel rectangles"), measured on OSMesa: each
 * check draws a 512 x 1 image, reads the raw 24-bit depths (OSMesaGetDepthBuffer) or the
 * stencil and colour bytes, and prints the number of pixels that break the stated rule (0
 * everywhere on Debian 12's Mesa 22.3).
 * Build: gcc pixel_values_probe.c $(pkg-config --cflags --libs osmesa) -lm */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 512
static OSMesaContext context;
static unsigned char buffer[W * 4 * 4];

static void report(const char* rule, int broken) { printf("%-78s broken by %d\n", rule, broken); }

static unsigned depthAt(int x) {
    GLint w, h, bytes;
    void* d;
    glFinish();
    OSMesaGetDepthBuffer(context, &w, &h, &bytes, &d);
    return ((unsigned*)d)[x] & 0xFFFFFF;
}

static float clampUnit(float z) { return z < 0 ? 0 : z > 1 ? 1 : z; }
/* llvmpipe's write of a fragment depth: round(clamp(z) * (2^24 - 1)) to even, in float. */
static unsigned depth24(float z) { return (unsigned)nearbyintf(clampUnit(z) * 16777215.0f); }
/* A 24-bit texel sampled: z * (1 / (2^24 - 1)) in float. */
static unsigned resampled(unsigned z) { return depth24((float)z * (1.0f / 16777215.0f)); }
/* A 32-bit unorm texel sampled: its top 23 bits over 2^23 - 1. */
static float unorm32(uint32_t t) {
    union {
        uint32_t u;
        float f;
    } v = {(t >> 9) | 0x3F800000u};
    return (v.f - 1.0f) * (float)(8388608.0 / 8388607.0);
}

static float depthFloat(const void* image, int i, GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE: return ((const GLubyte*)image)[i] / 255.0f;
    case GL_BYTE: {
        int b = ((const GLbyte*)image)[i];
        return b == 0 ? 0.0f : (2.0f * b + 1.0f) * (1.0f / 255.0f);
    }
    case GL_UNSIGNED_SHORT: return ((const GLushort*)image)[i] * (1.0f / 65535.0f);
    case GL_SHORT: {
        int s = ((const GLshort*)image)[i];
        return s == 0 ? 0.0f : (2.0f * s + 1.0f) * (1.0f / 65535.0f);
    }
    case GL_UNSIGNED_INT: return (float)(((const GLuint*)image)[i] * (1.0 / 4294967295.0));
    case GL_INT: return (float)((2.0f * (float)((const GLint*)image)[i] + 1.0f) * (1.0 / 4294967294.0));
    default: return ((const GLfloat*)image)[i];
    }
}

/* The rule: Mesa's texture store of the image (scale and bias, clamp), its texture by type
 * (16-bit for unsigned shorts, 32-bit for unsigned ints, float, else 24-bit truncated), sampled. */
static unsigned expectedDepth(const void* image, int i, GLenum type, float scale, float bias) {
    const int transfer = scale != 1.0f || bias != 0.0f;
    float z = depthFloat(image, i, type);
    if (transfer) z = z * scale + bias;
    if (transfer || type == GL_BYTE || type == GL_SHORT || type == GL_INT || type == GL_FLOAT) z = clampUnit(z);
    switch (type) {
    case GL_UNSIGNED_SHORT: {
        unsigned t = transfer ? (unsigned)(z * 65535.0f) : ((const GLushort*)image)[i];
        return depth24((float)t * (1.0f / 65535.0f));
    }
    case GL_UNSIGNED_INT: {
        uint32_t t = ((const GLuint*)image)[i];
        if (transfer) {
            double wide = (double)z * 4294967295.0;
            t = wide >= 4294967295.0 ? 0xFFFFFFFFu : (uint32_t)wide;
        }
        return depth24(unorm32(t));
    }
    case GL_FLOAT: return depth24(z);
    default: return resampled((unsigned)(z * 16777215.0f));
    }
}

static void fillImage(void* image, GLenum type) {
    for (int i = 0; i < W; i++) {
        uint32_t r = ((uint32_t)rand() << 16) ^ (uint32_t)rand() ^ ((uint32_t)rand() << 30);
        switch (type) {
        case GL_UNSIGNED_BYTE:
        case GL_BYTE: ((GLubyte*)image)[i] = (GLubyte)(i < 256 ? i : r); break;
        case GL_UNSIGNED_SHORT:
        case GL_SHORT:
            ((GLushort*)image)[i] = (GLushort)(i < 64 ? i : i < 128 ? 0xFFFF - i : i < 192 ? 0x7FFF - i + 128 : r);
            break;
        case GL_UNSIGNED_INT:
        case GL_INT:
            ((GLuint*)image)[i] = i < 64    ? (uint32_t)i << 8
                                  : i < 128 ? 0xFFFFFFFFu - ((uint32_t)i << 20)
                                  : i < 160 ? 0x7FFFFFFFu - (uint32_t)i * 97
                                            : r;
            break;
        default:
            ((GLfloat*)image)[i] = i < 64   ? (i - 8) / 48.0f
                                   : i < 96 ? 1.0f / (float)(i - 63)
                                            : (float)r / 4294967295.0f;
        }
    }
}

int main(void) {
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, W, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, 4, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT,  GL_INT,  GL_FLOAT};
    static const char* names[] = {"ubyte", "byte", "ushort", "short", "uint", "int", "float"};
    static const float transfers[][2] = {{1, 0}, {0.5f, 0.25f}, {2, -0.5f}, {-1, 1}};
    static uint32_t image[W];
    char rule[128];
    srand(1);
    for (int t = 0; t < 7; t++) {
        fillImage(image, types[t]);
        for (int k = 0; k < 4; k++) {
            /* A new image each time: the reference reuses the texture it made for an equal image
             * (same pointer, size, format, type, bytes and maps), under the transfer of then. */
            ((unsigned char*)image)[0] ^= (unsigned char)(1u << k);
            glPixelTransferf(GL_DEPTH_SCALE, transfers[k][0]);
            glPixelTransferf(GL_DEPTH_BIAS, transfers[k][1]);
            glRasterPos2i(0, 0);
            glDrawPixels(W, 1, GL_DEPTH_COMPONENT, types[t], image);
            int broken = 0;
            for (int i = 0; i < W; i++)
                broken += depthAt(i) != expectedDepth(image, i, types[t], transfers[k][0], transfers[k][1]);
            snprintf(rule, sizeof rule, "depth image, %s, scale %g bias %g: texture of the type, sampled", names[t],
                     transfers[k][0], transfers[k][1]);
            report(rule, broken);
        }
    }
    glPixelTransferf(GL_DEPTH_SCALE, 1);
    glPixelTransferf(GL_DEPTH_BIAS, 0);

    /* glCopyPixels of depth, zoomed (no blit): every value through the 24-bit texture. */
    {
        unsigned before[W];
        GLuint ramp[W];
        for (int i = 0; i < W; i++) ramp[i] = 0x60000000u + (uint32_t)i * 0x100u * 3u;
        glRasterPos2i(0, 1);
        glDrawPixels(W, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, ramp);
        glFinish();
        GLint w, h, bytes;
        void* d;
        OSMesaGetDepthBuffer(context, &w, &h, &bytes, &d);
        for (int i = 0; i < W; i++) before[i] = ((unsigned*)d)[W + i] & 0xFFFFFF;
        glPixelZoom(1, -1);
        glRasterPos2i(0, 1);
        glCopyPixels(0, 1, W, 1, GL_DEPTH);
        glPixelZoom(1, 1);
        int broken = 0;
        for (int i = 0; i < W; i++) broken += depthAt(i) != resampled(before[i]);
        report("depth copy (zoom 1, -1): z24 sampled as z * (1 / (2^24 - 1)), rounded again", broken);
    }

    /* Stencil images: index shift and offset never apply, MAP_STENCIL for every type but
     * unsigned bytes (each turned off before reading back: glReadPixels of stencil applies them). */
    {
        GLubyte s[W], indices[W], mapped[W];
        GLfloat map[8] = {3, 250, 17, 300, 42, 0, 128, 77};
        for (int i = 0; i < W; i++) indices[i] = (GLubyte)(i * 7), mapped[i] = (GLubyte)(i * 5);
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
        glPixelTransferi(GL_INDEX_SHIFT, 1);
        glPixelTransferi(GL_INDEX_OFFSET, 5);
        glRasterPos2i(0, 0);
        glDrawPixels(W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, indices);
        glPixelTransferi(GL_INDEX_SHIFT, 0);
        glPixelTransferi(GL_INDEX_OFFSET, 0);
        glReadPixels(0, 0, W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
        int broken = 0;
        for (int i = 0; i < W; i++) broken += s[i] != indices[i];
        report("stencil image: index shift and offset not applied", broken);
        glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 8, map);
        glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
        glDrawPixels(W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, mapped);
        glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
        glReadPixels(0, 0, W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
        broken = 0;
        for (int i = 0; i < W; i++) broken += s[i] != mapped[i];
        report("stencil image, unsigned bytes: GL_MAP_STENCIL not applied", broken);
        {
            static GLushort shorts[W];
            for (int i = 0; i < W; i++) shorts[i] = (GLushort)(i * 3);
            glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
            glDrawPixels(W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, shorts);
            glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
            glReadPixels(0, 0, W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
            broken = 0;
            for (int i = 0; i < W; i++) broken += s[i] != (((unsigned)map[shorts[i] & 7]) & 0xFF);
            report("stencil image, unsigned shorts: GL_MAP_STENCIL at index & (size - 1), 8 bits", broken);
        }
    }

    /* Colour-index images: I_TO_R..A maps, no shift or offset, bytes rounded into RGBA8. */
    {
        GLubyte c[W * 4], indices[W];
        GLfloat r[4] = {0, 0.3f, 0.71f, 1}, g[2] = {0.5f, 0.123f};
        for (int i = 0; i < W; i++) indices[i] = (GLubyte)(i * 13);
        glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
        glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, g);
        glPixelTransferi(GL_INDEX_OFFSET, 1);
        glRasterPos2i(0, 0);
        glDrawPixels(W, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
        glPixelTransferi(GL_INDEX_OFFSET, 0);
        glReadPixels(0, 0, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
        int broken = 0;
        for (int i = 0; i < W; i++) {
            broken += c[4 * i] != (GLubyte)lrintf(r[indices[i] & 3] * 255.0f) ||
                      c[4 * i + 1] != (GLubyte)lrintf(g[indices[i] & 1] * 255.0f) || c[4 * i + 2] != 0 ||
                      c[4 * i + 3] != 0;
        }
        report("colour-index image: maps of size n at index & (n - 1), no offset", broken);
    }
    /* Colour-index bitmaps: rows of 13 bits follow each other with no padding. */
    {
        static const GLubyte bits[8] = {0xA5, 0x3C, 0xFF, 0x00, 0x81, 0x7E, 0x0F, 0xF0};
        GLfloat r[2] = {0, 1};
        GLubyte c[W * 4 * 4];
        glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, r);
        glClear(GL_COLOR_BUFFER_BIT);
        glRasterPos2i(0, 0);
        glDrawPixels(13, 4, GL_COLOR_INDEX, GL_BITMAP, bits);
        glReadPixels(0, 0, W, 4, GL_RGBA, GL_UNSIGNED_BYTE, c);
        int broken = 0;
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 13; x++) {
                const int bit = y * 13 + x;
                broken += (c[(y * W + x) * 4] == 255) != ((bits[bit / 8] >> (7 - bit % 8)) & 1);
            }
        }
        report("colour-index bitmap: rows not padded to bytes (bit y * width + x)", broken);
    }
    OSMesaDestroyContext(context);
    return 0;
}
