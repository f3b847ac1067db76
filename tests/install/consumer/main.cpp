// Draws one triangle on MyGL and on OSMesa through the same GL table; exits 0 if both drew it.
#include <glad/gl.h>
#include <mygl/context.h>
#include <reference/osmesa_context.h>

#include <cstdio>

static void drawTriangle() {
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.0f, 0.5f);
    glEnd();
}

int main() {
    mygl::Context ours(16, 16);
    ours.makeCurrent();
    drawTriangle();
    const auto a = ours.readPixels();
    reference::OsmesaContext theirs(16, 16);
    theirs.makeCurrent();
    drawTriangle();
    const auto b = theirs.readPixels();
    const std::size_t center = (8 * 16 + 8) * 4;
    std::printf("center: mygl %d, osmesa %d\n", a[center], b[center]);
    return a == b && a[center] == 255 ? 0 : 1;
}
