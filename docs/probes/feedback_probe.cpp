// Probe: what OSMesa's GL_FEEDBACK writes (Mesa's st_cb_feedback.c behind the draw module):
// tokens for points, line strips and GL_LINES, triangles and quads, a clipped triangle, culling,
// polygon modes, flat shading, the texture coordinate, glPassThrough and glBitmap, overflow.
// Build: g++ -O1 feedback_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/feedback_probe
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <functional>
#include <vector>

static void run(const char* title, GLenum type, const std::function<void()>& draw, int size = 400) {
    std::vector<GLfloat> buffer(size, -7.0f);
    glFeedbackBuffer(size, type, buffer.data());
    glRenderMode(GL_FEEDBACK);
    draw();
    const GLint count = glRenderMode(GL_RENDER);
    std::printf("%s: %d values, error 0x%x\n ", title, count, glGetError());
    for (int i = 0; i < (count < 0 ? size : count); ++i) {
        const float v = buffer[i];
        if (v >= 1792 && v <= 1799)
            std::printf("\n  [%g]", v);
        else
            std::printf(" %.9g", v);
    }
    std::printf("\n");
}

int main() {
    std::vector<unsigned char> fb(40 * 30 * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, 40, 30);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -0.75, 0.75, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -2);
    glTexCoord4f(0.25f, 0.5f, 0.75f, 2.0f);
    const auto tri = [] {
        glBegin(GL_TRIANGLES);
        glColor4f(1, 0, 0, 1);
        glVertex3f(-1, -1, 0);
        glColor4f(0, 1, 0, 0.5f);
        glVertex3f(1, -1, 0.5f);
        glColor4f(0, 0, 1, 0.25f);
        glVertex3f(0, 1, -0.5f);
        glEnd();
    };
    run("triangle 3D_COLOR_TEXTURE", GL_3D_COLOR_TEXTURE, tri);
    run("triangle 4D_COLOR_TEXTURE", GL_4D_COLOR_TEXTURE, tri);
    run("triangle 2D", GL_2D, tri);
    run("triangle 3D", GL_3D, tri);
    run("triangle 3D_COLOR", GL_3D_COLOR, tri);
    glShadeModel(GL_FLAT);
    run("flat triangle", GL_3D_COLOR, tri);
    glShadeModel(GL_SMOOTH);
    run("quad 2D", GL_2D, [] {
        glBegin(GL_QUADS);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1, 1);
        glVertex2f(-1, 1);
        glEnd();
    });
    run("polygon 5 2D", GL_2D, [] {
        glBegin(GL_POLYGON);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1.2f, 0.3f);
        glVertex2f(0, 1);
        glVertex2f(-1, 0.5f);
        glEnd();
    });
    run("clipped triangle 3D", GL_3D, [] {
        glBegin(GL_TRIANGLES);
        glVertex2f(-3, -0.5f);
        glVertex2f(0.5f, -0.5f);
        glVertex2f(0, 3);
        glEnd();
    });
    run("lines and strip 2D", GL_2D, [] {
        glBegin(GL_LINES);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1, 1);
        glVertex2f(-1, 1);
        glEnd();
        glBegin(GL_LINE_STRIP);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1, 1);
        glEnd();
        glBegin(GL_LINE_LOOP);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1, 1);
        glEnd();
    });
    run("points 3D_COLOR, one outside", GL_3D_COLOR, [] {
        glPointSize(4);
        glBegin(GL_POINTS);
        glColor3f(1, 1, 0);
        glVertex2f(0.5f, 0.25f);
        glVertex2f(5, 0);
        glVertex2f(-0.5f, -0.25f);
        glEnd();
        glPointSize(1);
    });
    glEnable(GL_CULL_FACE);
    run("culled (cw) and kept (ccw)", GL_2D, [] {
        glBegin(GL_TRIANGLES);
        glVertex2f(-1, -1);
        glVertex2f(0, 1);
        glVertex2f(1, -1);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(0, 1);
        glEnd();
    });
    glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    run("line mode quad with an edge flag off", GL_2D, [] {
        glBegin(GL_QUADS);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glEdgeFlag(GL_FALSE);
        glVertex2f(1, 1);
        glEdgeFlag(GL_TRUE);
        glVertex2f(-1, 1);
        glEnd();
    });
    run("line mode triangle", GL_2D, [] {
        glBegin(GL_TRIANGLES);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(0, 1);
        glEnd();
    });
    run("line mode polygon", GL_2D, [] {
        glBegin(GL_POLYGON);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1, 1);
        glVertex2f(-1, 1);
        glEnd();
    });
    glPolygonMode(GL_FRONT, GL_FILL);
    run("front fill, back line: a back triangle", GL_2D, [] {
        glBegin(GL_TRIANGLES);
        glVertex2f(-1, -1);
        glVertex2f(0, 1);
        glVertex2f(1, -1);
        glEnd();
    });
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    run("point mode quad with an edge flag off", GL_2D, [] {
        glBegin(GL_QUADS);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glEdgeFlag(GL_FALSE);
        glVertex2f(1, 1);
        glEdgeFlag(GL_TRUE);
        glVertex2f(-1, 1);
        glEnd();
    });
    run("point mode triangle", GL_2D, [] {
        glBegin(GL_TRIANGLES);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(0, 1);
        glEnd();
    });
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    run("pass through, bitmap, raster pos", GL_3D_COLOR_TEXTURE, [] {
        glPassThrough(42.5f);
        glColor3f(0.5f, 0.25f, 1);
        glRasterPos2f(0.25f, 0.5f);
        const GLubyte bits[2] = {0xFF, 0xFF};
        glBitmap(8, 2, 0, 0, 3, 1, bits);
        glRasterPos2f(5, 5);
        glBitmap(8, 2, 0, 0, 3, 1, bits);
        glBegin(GL_POINTS);
        glVertex2f(0, 0);
        glEnd();
        glPassThrough(7);
    });
    run("overflow (size 10)", GL_3D, tri, 10);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    run("lit triangle", GL_3D_COLOR, tri);
    glDisable(GL_LIGHTING);
    // Errors and queries.
    while (glGetError()) {
    }
    GLfloat buf[8];
    glFeedbackBuffer(-1, GL_2D, buf);
    std::printf("negative size: 0x%x\n", glGetError());
    glFeedbackBuffer(8, GL_RGBA, buf);
    std::printf("bad type: 0x%x\n", glGetError());
    glFeedbackBuffer(8, GL_3D, nullptr);
    std::printf("null buffer: 0x%x\n", glGetError());
    glFeedbackBuffer(8, GL_3D, buf);
    std::printf("ok: 0x%x\n", glGetError());
    GLint v;
    glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &v);
    std::printf("size %d\n", v);
    glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &v);
    std::printf("type 0x%x\n", v);
    void* p;
    glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
    std::printf("pointer ok %d\n", p == buf);
    glRenderMode(GL_FEEDBACK);
    glFeedbackBuffer(8, GL_3D, buf);
    std::printf("in feedback mode: 0x%x\n", glGetError());
    glGetIntegerv(GL_RENDER_MODE, &v);
    std::printf("render mode 0x%x\n", v);
    glPassThrough(1);
    std::printf("to select: %d\n", glRenderMode(GL_SELECT));
    std::printf("error 0x%x\n", glGetError());
    glRenderMode(GL_RENDER);
    glFeedbackBuffer(0, GL_3D, buf);
    std::printf("size 0: 0x%x\n", glGetError());
    glRenderMode(GL_FEEDBACK);
    std::printf("feedback with size 0: 0x%x\n", glGetError());
    glRenderMode(GL_RENDER);
    glPassThrough(1);
    std::printf("pass through in render: 0x%x\n", glGetError());
    glBegin(GL_POINTS);
    glPassThrough(1);
    glEnd();
    std::printf("pass through in begin/end: 0x%x\n", glGetError());
    OSMesaDestroyContext(ctx);
}
