// Probe: OSMesa's accumulation buffer (GL_RGBA16_SNORM words, Mesa's main/accum.c). Draws every
// 8-bit value with glDrawPixels, runs glAccum sequences and compares the result with a model of
// the arithmetic; prints the mismatches of each candidate rounding.
// Build: g++ -O1 -std=c++20 accum_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/accum_probe
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

static const int W = 256, H = 4;
static std::vector<unsigned char> fb(W* H * 4);

static short toShort(float f) { return static_cast<short>(static_cast<int>(f)); }
static float unorm(int x, bool divide) { return divide ? x / 255.0f : x * (1.0f / 255.0f); }
static int pack(float f) {
    if (!(f > 0.0f)) return 0;
    if (f >= 1.0f) return 255;
    return static_cast<int>(std::nearbyint(f * 255.0f));
}

struct Op {
    GLenum op;
    float value;
};

int main() {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, W, H);
    GLint bits[4];
    glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
    glGetIntegerv(GL_ACCUM_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_ACCUM_BLUE_BITS, &bits[2]);
    glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
    std::printf("accum bits %d %d %d %d\n", bits[0], bits[1], bits[2], bits[3]);
    std::vector<unsigned char> row(W * 4);
    for (int i = 0; i < W; ++i)
        for (int c = 0; c < 4; ++c) row[i * 4 + c] = static_cast<unsigned char>((i + 37 * c) & 255);
    const std::vector<std::vector<Op>> sequences = {
        {{GL_LOAD, 1.0f}, {GL_RETURN, 1.0f}},
        {{GL_LOAD, 0.125f}, {GL_RETURN, 8.0f}},
        {{GL_LOAD, 0.3f}, {GL_ACCUM, 0.3f}, {GL_ACCUM, 0.4f}, {GL_RETURN, 1.0f}},
        {{GL_LOAD, 1.0f / 7}, {GL_ACCUM, 1.0f / 7}, {GL_RETURN, 3.5f}},
        {{GL_LOAD, 0.5f}, {GL_ADD, 0.1f}, {GL_MULT, 1.3f}, {GL_RETURN, 1.0f}},
        {{GL_LOAD, 0.9f}, {GL_ACCUM, 0.9f}, {GL_RETURN, 0.5f}},  // overflow of the words
        {{GL_LOAD, 1.0f}, {GL_MULT, 3.0f}, {GL_RETURN, 1.0f}},   // overflow through MULT
        {{GL_LOAD, 1.0f}, {GL_ADD, -0.6f}, {GL_RETURN, 2.0f}},
        {{GL_LOAD, -1.0f}, {GL_RETURN, -1.0f}},
        {{GL_LOAD, 1.0f}, {GL_MULT, 1e12f}, {GL_RETURN, 1.0f}},
    };
    for (int divide = 0; divide < 2; ++divide) {
        int total = 0;
        for (const auto& seq : sequences) {
            glRasterPos2i(-1, -1);
            glDrawPixels(W, 1, GL_RGBA, GL_UNSIGNED_BYTE, row.data());
            for (const Op& o : seq) glAccum(o.op, o.value);
            glFinish();
            int bad = 0;
            for (int i = 0; i < W * 4; ++i) {
                short acc = 0;
                int out = fb[i];
                for (const Op& o : seq) {
                    const float scale = o.value * 32767.0f;
                    switch (o.op) {
                    case GL_LOAD: acc = toShort(unorm(row[i], divide) * scale); break;
                    case GL_ACCUM: acc = static_cast<short>(acc + toShort(unorm(row[i], divide) * scale)); break;
                    case GL_ADD: acc = static_cast<short>(acc + toShort(o.value * 32767.0f)); break;
                    case GL_MULT: acc = toShort(acc * o.value); break;
                    case GL_RETURN: out = pack(acc * (o.value / 32767.0f)); break;
                    }
                }
                if (out != fb[i]) {
                    if (bad < 3) std::printf("  [%d] in %d got %d model %d\n", i, row[i], fb[i], out);
                    ++bad;
                }
            }
            total += bad;
            std::printf("divide=%d sequence %zu: %d mismatches\n", divide, &seq - sequences.data(), bad);
        }
        std::printf("divide=%d total %d\n", divide, total);
    }
    // Clear: glClearAccum value c then RETURN 1: FLOAT_TO_SHORT
    int bad = 0;
    for (int k = -300; k <= 300; ++k) {
        const float c = k / 256.0f;
        glClearAccum(c, c * 0.5f, c * 0.25f, 1.0f);
        glClear(GL_ACCUM_BUFFER_BIT);
        glAccum(GL_RETURN, 1.0f);
        glFinish();
        const float cs[4] = {c, c * 0.5f, c * 0.25f, 1.0f};
        for (int ch = 0; ch < 4; ++ch) {
            const float cl = std::fmax(-1.0f, std::fmin(1.0f, cs[ch]));
            const short s = static_cast<short>((static_cast<int>(65535.0f * cl) - 1) / 2);
            const int out = pack(s * (1.0f / 32767.0f));
            if (out != fb[ch]) {
                if (bad < 3) std::printf("  clear %g got %d model %d\n", cs[ch], fb[ch], out);
                ++bad;
            }
        }
    }
    std::printf("clear mismatches %d\n", bad);
    GLfloat cv[4];
    glClearAccum(2, -3, 0.5f, 0.25f);
    glGetFloatv(GL_ACCUM_CLEAR_VALUE, cv);
    std::printf("ACCUM_CLEAR_VALUE %g %g %g %g\n", cv[0], cv[1], cv[2], cv[3]);
    GLint iv[4];
    glGetIntegerv(GL_ACCUM_CLEAR_VALUE, iv);
    std::printf("ACCUM_CLEAR_VALUE int %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3]);
    while (glGetError()) {
    }
    glAccum(GL_ZERO, 1);
    std::printf("bad op: 0x%x\n", glGetError());
    glBegin(GL_POINTS);
    glAccum(GL_LOAD, 1);
    glEnd();
    std::printf("inside begin/end: 0x%x\n", glGetError());
    glNewList(1, GL_COMPILE);
    glAccum(GL_ZERO, 1);
    glEndList();
    std::printf("bad op compiled: 0x%x\n", glGetError());
    glClearIndex(3.7f);
    glIndexMask(0x5);
    glIndexf(2.5f);
    GLfloat f;
    GLint i;
    glGetFloatv(GL_INDEX_CLEAR_VALUE, &f);
    std::printf("INDEX_CLEAR_VALUE %g\n", f);
    glGetIntegerv(GL_INDEX_WRITEMASK, &i);
    std::printf("INDEX_WRITEMASK %d\n", i);
    glGetFloatv(GL_CURRENT_INDEX, &f);
    std::printf("CURRENT_INDEX %g\n", f);
    glGetIntegerv(GL_CURRENT_INDEX, &i);
    std::printf("CURRENT_INDEX int %d\n", i);
    glGetIntegerv(GL_INDEX_BITS, &i);
    std::printf("INDEX_BITS %d\n", i);
    glGetIntegerv(GL_INDEX_MODE, &i);
    std::printf("INDEX_MODE %d\n", i);
    glGetIntegerv(GL_RGBA_MODE, &i);
    std::printf("RGBA_MODE %d err 0x%x\n", i, glGetError());
    glGetIntegerv(GL_DRAW_BUFFER, &i);
    std::printf("DRAW_BUFFER 0x%x\n", i);
    glGetIntegerv(GL_READ_BUFFER, &i);
    std::printf("READ_BUFFER 0x%x\n", i);
    glGetIntegerv(GL_AUX_BUFFERS, &i);
    std::printf("AUX_BUFFERS %d\n", i);
    glGetIntegerv(GL_STEREO, &i);
    std::printf("STEREO %d\n", i);
    while (glGetError()) {
    }
    const GLenum bufs[] = {GL_NONE,  GL_FRONT_LEFT, GL_FRONT_RIGHT, GL_BACK_LEFT, GL_BACK_RIGHT,
                           GL_FRONT, GL_BACK,       GL_LEFT,        GL_RIGHT,     GL_FRONT_AND_BACK,
                           GL_AUX0,  GL_AUX1,       GL_COLOR_INDEX};
    for (GLenum b : bufs) {
        glDrawBuffer(b);
        GLenum e1 = glGetError();
        glGetIntegerv(GL_DRAW_BUFFER, &i);
        std::printf("glDrawBuffer(0x%x): err 0x%x now 0x%x\n", b, e1, i);
        glReadBuffer(b);
        e1 = glGetError();
        glGetIntegerv(GL_READ_BUFFER, &i);
        std::printf("glReadBuffer(0x%x): err 0x%x now 0x%x\n", b, e1, i);
    }
    OSMesaDestroyContext(ctx);
}
