// Probe: how OSMesa (Mesa 22.3 llvmpipe) draws GL_POINT_SMOOTH and GL_LINE_SMOOTH, and the size
// and width ranges it answers. Prints the alpha of every pixel of a smooth point (colour alpha
// 0.8, blending off: the written alpha is the fragment's, coverage included) and of a smooth line.
// Build: g++ -O1 smooth_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/smooth_probe
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <vector>

constexpr int kWidth = 16, kHeight = 12;

static void printAlpha(const char* title) {
    std::vector<GLubyte> rgba(kWidth * kHeight * 4);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    std::printf("%s (alpha, top row first; . = not written)\n", title);
    for (int y = kHeight - 1; y >= 0; --y) {
        for (int x = 0; x < kWidth; ++x) {
            const GLubyte a = rgba[(y * kWidth + x) * 4 + 3];
            if (a == 7)
                std::printf("   .");
            else
                std::printf(" %3d", a);
        }
        std::printf("\n");
    }
}

static void clear() {
    glClearColor(0, 0, 0, 7 / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

int main() {
    std::vector<unsigned char> fb(kWidth * kHeight * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, kWidth, kHeight);
    const GLenum names[] = {GL_POINT_SIZE_RANGE,
                            GL_POINT_SIZE_GRANULARITY,
                            GL_LINE_WIDTH_RANGE,
                            GL_LINE_WIDTH_GRANULARITY,
                            0x846D /* GL_ALIASED_POINT_SIZE_RANGE */,
                            0x846E /* GL_ALIASED_LINE_WIDTH_RANGE */};
    const char* labels[] = {"POINT_SIZE_RANGE (= SMOOTH_)", "POINT_SIZE_GRANULARITY",   "LINE_WIDTH_RANGE (= SMOOTH_)",
                            "LINE_WIDTH_GRANULARITY",       "ALIASED_POINT_SIZE_RANGE", "ALIASED_LINE_WIDTH_RANGE"};
    for (int i = 0; i < 6; ++i) {
        GLfloat v[2] = {-1, -1};
        glGetFloatv(names[i], v);
        std::printf("%s: %g %g (error 0x%x)\n", labels[i], v[0], v[1], glGetError());
    }
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glColor4f(1.0f, 0.5f, 0.25f, 0.8f);  // alpha 204

    glEnable(GL_POINT_SMOOTH);
    for (float size : {1.0f, 4.0f, 7.0f}) {
        clear();
        glPointSize(size);
        glBegin(GL_POINTS);
        glVertex2f(8.0f, 6.0f);
        glEnd();
        char title[64];
        std::snprintf(title, sizeof title, "smooth point, size %g at (8, 6)", size);
        printAlpha(title);
    }
    glDisable(GL_POINT_SMOOTH);

    glEnable(GL_LINE_SMOOTH);
    for (float width : {1.0f, 3.0f}) {
        clear();
        glLineWidth(width);
        glBegin(GL_LINES);
        glVertex2f(2.5f, 3.0f);
        glVertex2f(13.0f, 8.5f);
        glEnd();
        char title[64];
        std::snprintf(title, sizeof title, "smooth line, width %g, (2.5, 3) to (13, 8.5)", width);
        printAlpha(title);
    }
    clear();
    glLineWidth(1.0f);
    glBegin(GL_LINES);
    glVertex2f(5.0f, 5.0f);
    glVertex2f(5.0f, 5.0f);
    glEnd();
    printAlpha("smooth line of length 0 at (5, 5)");
    OSMesaDestroyContext(ctx);
}
