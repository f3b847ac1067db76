// Probe: the reference's answers where the API conformance cases found it departing from GL 1.1:
// a negative array stride, GL_PIXEL_MAP_I_TO_I of a size that is not a power of two, a bad
// internal format to glCopyTexImage, a texture priority asked as an integer.
// Build: g++ -O1 api_departures_probe.cpp $(pkg-config --cflags --libs osmesa) -o /tmp/api_departures_probe
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <cstdio>
#include <vector>
int main() {
    std::vector<unsigned char> fb(16 * 16 * 4);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
    OSMesaMakeCurrent(ctx, fb.data(), GL_UNSIGNED_BYTE, 16, 16);
    static const float v[8] = {};
    GLint size, type, stride;
    glVertexPointer(3, GL_FLOAT, 0, v);
    glVertexPointer(2, GL_SHORT, -1, v);
    GLenum error = glGetError();
    glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &size);
    glGetIntegerv(GL_VERTEX_ARRAY_TYPE, &type);
    glGetIntegerv(GL_VERTEX_ARRAY_STRIDE, &stride);
    std::printf("glVertexPointer(2, GL_SHORT, -1): error 0x%x, size %d type 0x%x stride %d (spec: 3, GL_FLOAT, 0)\n", error, size,
                type, stride);

    static const GLuint map[3] = {3, 2, 1};
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 3, map);
    error = glGetError();
    glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE, &size);
    std::printf("glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 3): error 0x%x, size %d (spec: GL_INVALID_VALUE, 1)\n", error, size);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 3, map);
    std::printf("glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 3): error 0x%x\n", glGetError());

    glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x9999, 0, 0, 4, 4, 0);
    std::printf("glCopyTexImage2D(internal format 0x9999): error 0x%x (spec: GL_INVALID_VALUE)\n", glGetError());
    static const unsigned char texels[64] = {};
    glTexImage2D(GL_TEXTURE_2D, 0, 0x9999, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    std::printf("glTexImage2D(internal format 0x9999): error 0x%x\n", glGetError());

    GLuint name = 7;
    const GLclampf priority = 0.25f;
    glBindTexture(GL_TEXTURE_2D, name);
    glPrioritizeTextures(1, &name, &priority);
    GLint asInteger;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &asInteger);
    std::printf("glGetTexParameteriv(GL_TEXTURE_PRIORITY) of 0.25: %d (spec: rounded, 0)\n", asInteger);
    OSMesaDestroyContext(ctx);
}
