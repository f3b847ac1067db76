// Probe: the reference's answers where the API conformance cases found it departing from GL 1.1:
// a negative array stride, GL_PIXEL_MAP_I_TO_I of a size that is not a power of two, a bad
// internal format to glCopyTexImage, a texture priority asked as an integer; and compiled into a
// display list: glClearIndex, glPrioritizeTextures with a negative count, glDrawElements with a
// bad type, glMap1f with a stride too small, glNewList.
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
    std::printf("glVertexPointer(2, GL_SHORT, -1): error 0x%x, size %d type 0x%x stride %d (spec: 3, GL_FLOAT, 0)\n",
                error, size, type, stride);

    static const GLuint map[3] = {3, 2, 1};
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 3, map);
    error = glGetError();
    glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE, &size);
    std::printf("glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 3): error 0x%x, size %d (spec: GL_INVALID_VALUE, 1)\n", error,
                size);
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

    glNewList(1, GL_COMPILE);
    glClearIndex(7.5f);
    glPrioritizeTextures(-1, &name, &priority);
    glEndList();
    glCallList(1);
    float index;
    glGetFloatv(GL_INDEX_CLEAR_VALUE, &index);
    std::printf(
        "list of glClearIndex(7.5), glPrioritizeTextures(-1): error 0x%x, GL_INDEX_CLEAR_VALUE %g (spec: "
        "GL_INVALID_VALUE, 7)\n",
        glGetError(), index);
    static const GLushort indices[3] = {0, 1, 2};
    glNewList(2, GL_COMPILE);
    glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, indices);
    glEndList();
    std::printf("glDrawElements(GL_FLOAT indices) compiled: error 0x%x", glGetError());
    glCallList(2);
    std::printf(", run: error 0x%x (spec: GL_INVALID_ENUM when run)\n", glGetError());
    static const float points[12] = {0, 0, 0, 1, 1, 0, 2, 0, 0, 3, 1, 0};
    glNewList(3, GL_COMPILE);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 2, 4, points);
    glEndList();
    glCallList(3);
    GLint order;
    glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
    std::printf("list of glMap1f(stride 2 < 3): error 0x%x, order %d (spec: GL_INVALID_VALUE, 1)\n", glGetError(),
                order);
    glNewList(4, GL_COMPILE);
    glNewList(0, GL_COMPILE);
    std::printf("glNewList(0) while compiling: error 0x%x\n", glGetError());
    glEndList();
    OSMesaDestroyContext(ctx);
}
