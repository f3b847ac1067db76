// Probe: queries between a glBegin given while compiling a GL_COMPILE_AND_EXECUTE list and its
// glEnd. GL executes the glBegin as it compiles it, so a glGet there is inside glBegin/glEnd
// (GL_INVALID_OPERATION, nothing written); the reference answers them as outside.
// Build: g++ -O1 query_inside_executed_list_begin_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/q
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <vector>
int main() {
    std::vector<unsigned char> fb(4 * 4 * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, 4, 4);
    for (GLenum mode : {GL_COMPILE_AND_EXECUTE, GL_COMPILE}) {
        glNewList(1, mode);
        glBegin(GL_POINTS);
        GLint size = -1;
        glGetIntegerv(GL_POINT_SIZE, &size);
        const GLenum getError = glGetError();
        const GLubyte* vendor = glGetString(GL_VENDOR);
        const GLenum stringError = glGetError();
        const GLboolean enabled = glIsEnabled(GL_DEPTH_TEST);
        const GLenum isEnabledError = glGetError();
        glEnd();
        glEndList();
        std::printf(
            "%s: glGetIntegerv(GL_POINT_SIZE) %d error 0x%x; glGetString %s error 0x%x; glIsEnabled %d "
            "error 0x%x\n",
            mode == GL_COMPILE ? "GL_COMPILE" : "GL_COMPILE_AND_EXECUTE", size, getError, vendor ? "a string" : "NULL",
            stringError, enabled, isEnabledError);
    }
    glBegin(GL_POINTS);
    GLint size = -1;
    glGetIntegerv(GL_POINT_SIZE, &size);
    const GLenum error = glGetError();
    glEnd();
    std::printf("no list: glGetIntegerv(GL_POINT_SIZE) %d error 0x%x (0x%x after glEnd)\n", size, error, glGetError());
    OSMesaDestroyContext(ctx);
}
