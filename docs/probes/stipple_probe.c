/* Polygon and line stipple on OSMesa (issue 16): which pixels a 32x32 pattern keeps (window y
 * from the bottom, an odd framebuffer height; the first byte's high bit is x = 0), whether lines
 * and points are stippled, glLineStipple's factor clamping, and the line stipple counter along a
 * strip (pixels lit along two segments of fractional length).
 * Build: gcc stipple_probe.c $(pkg-config --cflags --libs osmesa) -o stipple_probe */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

#define W 40
#define H 37
static unsigned char buf[W * H * 4];

static int lit(int y) {
    int x, n = 0;
    for (x = 0; x < W; x++) n += buf[(y * W + x) * 4] != 0;
    return n;
}

int main(void) {
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    GLubyte pattern[128], back[128];
    GLint v;
    int x, y;
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    memset(pattern, 0, sizeof pattern);
    pattern[0] = 0x80;         /* row 0: x = 0 */
    pattern[4] = 0x01;         /* row 1: x = 7 */
    pattern[4 * 2 + 3] = 0x01; /* row 2: x = 31 */
    glPolygonStipple(pattern);
    glEnable(GL_POLYGON_STIPPLE);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glVertex2f(0, 0), glVertex2f(W, 0), glVertex2f(W, H), glVertex2f(0, H);
    glEnd();
    glBegin(GL_LINES); /* a line along row 5: not stippled */
    glVertex2f(0, 5.5f), glVertex2f(W, 5.5f);
    glEnd();
    glBegin(GL_POINTS); /* a point at (1, 6): not stippled */
    glVertex2f(1.5f, 6.5f);
    glEnd();
    glFinish();
    for (y = H - 1; y >= 0; y--) { /* OSMesa's rows from the bottom */
        for (x = 0; x < W; x++) putchar(buf[(y * W + x) * 4] ? '#' : '.');
        printf("  y=%d\n", y);
    }
    glGetPolygonStipple(back);
    printf("glGetPolygonStipple: %02x %02x %02x\n", back[0], back[4], back[11]);
    glLineStipple(0, 0xFFFF);
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &v);
    printf("factor 0 -> %d, error 0x%x\n", v, glGetError());
    glLineStipple(300, 0xFFFF);
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &v);
    printf("factor 300 -> %d, error 0x%x\n", v, glGetError());

    /* The counter along a strip: segments of 10.5 and 10.5 pixels on row 10, pattern 0x5555
     * (every other pixel). Growing by ceil(length) = 11 the second segment starts on an odd
     * count (off); growing by 10.5 it would start on count 10 (on). */
    glDisable(GL_POLYGON_STIPPLE);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x5555);
    glBegin(GL_LINE_STRIP);
    glVertex2f(2.0f, 10.5f), glVertex2f(12.5f, 10.5f), glVertex2f(23.0f, 10.5f);
    glEnd();
    glFinish();
    for (x = 0; x < W; x++) putchar(buf[(10 * W + x) * 4] ? '#' : '.');
    printf("  strip, %d pixels lit\n", lit(10));
    return 0;
}
