/* Which state a cached glBitmap is drawn with when state changes between glBitmap and the next
 * draw: the state at glBitmap, or at the draw that flushes the cache? Per operation.
 * cc bitmap_cache_state_probe.c $(pkg-config --cflags --libs osmesa) -o probe && ./probe */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>

static unsigned char buf[16 * 16 * 4];
static const GLubyte bits[2] = {0xFF, 0xFF};

static void bitmapThenDraw(void (*before)(void), void (*after)(void), const char* name) {
    GLubyte stencil = 0;
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_COLOR_LOGIC_OP);
    glColorMask(1, 1, 1, 1);
    glClearColor(0, 0, 0, 0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    before();
    glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
    glRasterPos2f(-1, -1);
    glBitmap(8, 1, 0, 0, 0, 0, bits);
    after();
    glBegin(GL_POINTS);
    glVertex2f(0.9f, 0.9f);
    glEnd(); /* a draw elsewhere */
    glFinish();
    glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
    printf("%-12s pixel %3u %3u %3u %3u stencil %u\n", name, buf[0], buf[1], buf[2], buf[3], stencil);
}

static void stencilReplace(void) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 5, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
}
static void stencilNever(void) { glStencilFunc(GL_NEVER, 9, 0xFF); }
static void nothing(void) {}
static void blendOn(void) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
}
static void alphaNever(void) {
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_NEVER, 0);
}
static void maskRed(void) { glColorMask(1, 0, 0, 0); }
static void scissorAway(void) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(8, 8, 4, 4);
}
static void depthNever(void) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER);
}
static void logicInvert(void) {
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_COPY_INVERTED);
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    bitmapThenDraw(nothing, nothing, "plain");
    bitmapThenDraw(stencilReplace, stencilNever, "stencil");
    bitmapThenDraw(nothing, blendOn, "blend");
    bitmapThenDraw(nothing, alphaNever, "alpha");
    bitmapThenDraw(nothing, maskRed, "colormask");
    bitmapThenDraw(nothing, scissorAway, "scissor");
    bitmapThenDraw(nothing, depthNever, "depth");
    bitmapThenDraw(nothing, logicInvert, "logicop");
    OSMesaDestroyContext(ctx);
    return 0;
}
