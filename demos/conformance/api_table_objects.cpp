// The API table's object and image functions: glBegin/glEnd, display lists, vertex arrays,
// pixel rectangles and maps, selection and feedback, evaluators.
#include <glad/gl.h>

#include <algorithm>

#include "api_table.h"

namespace conformance {
namespace {

constexpr GLenum kBad = kBadEnum;

// Images and arrays at fixed addresses: the GL keeps pointers to some of them after the call.
GLubyte texels[8 * 8 * 4];
GLuint selectBuffer[64];
GLfloat feedbackBuffer[64];
const GLfloat kTriangle[6] = {-0.6f, -0.5f, 0.7f, -0.4f, 0.0f, 0.6f};
const GLubyte kColors[12] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128};
const GLfloat kInterleaved[18] = {1, 0, 0, -0.6f, -0.5f, 0.1f, 0, 1, 0, 0.7f, -0.4f, 0.2f, 0, 0, 1, 0.0f, 0.6f, 0.3f};
const GLushort kIndices[3] = {2, 0, 1};
const GLubyte kByteIndices[3] = {1, 2, 0};
const GLfloat kCurve[12] = {-0.8f, -0.6f, 0.0f, 0.0f, 0.9f, 0.2f, 0.8f, -0.5f, 0.0f, 0.5f, 0.5f, 0.0f};
const GLdouble kCurveD[12] = {-0.8, -0.6, 0.0, 0.0, 0.9, 0.2, 0.8, -0.5, 0.0, 0.5, 0.5, 0.0};
// Data as long as a bad count says (a list compiles the call, copying what the count implies).
const GLfloat kLongF[512] = {};
const GLdouble kLongD[1024] = {};

void triangleVertices() {
    glVertex2f(-0.6f, -0.5f);
    glVertex2f(0.7f, -0.4f);
    glVertex2f(0.0f, 0.6f);
}

void deleteLists(Observations&) {
    glDeleteLists(1, 100);
    glListBase(0);
}

// List 20: a green rectangle.
void rectangleList(GLuint name, GLenum mode) {
    glNewList(name, mode);
    glColor3f(0.2f, 0.9f, 0.3f);
    glRectf(-0.3f, -0.2f, 0.4f, 0.5f);
    glEndList();
}

void listState(Observations& o) {
    o.value("glIsList(20)", glIsList(20));
    o.get({GL_LIST_INDEX, GL_LIST_MODE, GL_LIST_BASE});
}

void vertexArrays() {
    glVertexPointer(2, GL_FLOAT, 0, kTriangle);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, kColors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
}

void disableArrays(Observations&) {
    for (GLenum a :
         {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY})
        glDisableClientState(a);
    glColor4f(1, 1, 1, 1);
}

ApiCall arrayState(GLenum array, GLenum pointerName, const void* expected, std::vector<unsigned> pnames) {
    return [=, q = get(std::move(pnames))](Observations& o) {
        q(o);
        void* p = nullptr;
        glGetPointerv(pointerName, &p);
        o.value("pointer is the array", p == expected);
        o.value("enabled", glIsEnabled(array));
    };
}

void popClientAttribs(Observations&) {
    for (int i = 0; i < 20; ++i) glPopClientAttrib();
}

// A bitmap or image drawn at a raster position.
void rasterAt(float x, float y) { glRasterPos2f(x, y); }

void readPixels(Observations& o) {
    GLubyte back[4 * 6 * 4];
    std::fill(std::begin(back), std::end(back), GLubyte{0xA5});
    glReadPixels(10, 10, 4, 6, GL_RGBA, GL_UNSIGNED_BYTE, back);
    o.bytes("glReadPixels", back, sizeof back);
}

void resetPixelModes(Observations&) {
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_MAP_COLOR, 0);
    const GLfloat identity[1] = {0.0f};
    const GLuint zero[1] = {0};
    const GLushort zeroS[1] = {0};
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, identity);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 1, zero);
    glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 1, zeroS);
    glPixelZoom(1.0f, 1.0f);
}

ApiCall pixelMap(GLenum map) {
    return [map](Observations& o) {
        o.get({GL_PIXEL_MAP_R_TO_R_SIZE, GL_PIXEL_MAP_I_TO_I_SIZE, GL_PIXEL_MAP_S_TO_S_SIZE});
        GLfloat f[8];
        GLuint u[8];
        GLushort s[8];
        std::fill(std::begin(f), std::end(f), Observations::kUnwritten);
        std::fill(std::begin(u), std::end(u), 77u);
        std::fill(std::begin(s), std::end(s), GLushort{77});
        glGetPixelMapfv(map, f);
        glGetPixelMapuiv(map, u);
        glGetPixelMapusv(map, s);
        o.floats("glGetPixelMapfv", f, 8);
        o.uints("glGetPixelMapuiv", u, 8);
        GLuint widened[8];
        std::copy(std::begin(s), std::end(s), widened);
        o.uints("glGetPixelMapusv", widened, 8);
    };
}

// Selection of a triangle under the names the row's calls push, with the hit records.
template <class Names>
void selectTriangle(Observations& o, Names names) {
    std::fill(std::begin(selectBuffer), std::end(selectBuffer), 0xA5A5A5A5u);
    glSelectBuffer(64, selectBuffer);
    glRenderMode(GL_SELECT);
    names();
    glBegin(GL_TRIANGLES);
    triangleVertices();
    glEnd();
    o.get({GL_NAME_STACK_DEPTH});
    o.value("hits", glRenderMode(GL_RENDER));
    o.uints("select buffer", selectBuffer, 64);
}

void renderMode(Observations&) { glRenderMode(GL_RENDER); }

ApiCall mapState(GLenum target) {
    return [target](Observations& o) {
        for (GLenum query : {GL_ORDER, GL_DOMAIN, GL_COEFF}) {
            GLdouble d[16];
            GLfloat f[16];
            GLint i[16];
            std::fill(std::begin(d), std::end(d), static_cast<GLdouble>(Observations::kUnwritten));
            std::fill(std::begin(f), std::end(f), Observations::kUnwritten);
            std::fill(std::begin(i), std::end(i), -12345);
            glGetMapdv(target, query, d);
            glGetMapfv(target, query, f);
            glGetMapiv(target, query, i);
            o.doubles("glGetMapdv", d, 16);
            o.floats("glGetMapfv", f, 16);
            o.ints("glGetMapiv", i, 16);
        }
    };
}

void curve() {
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, kCurve);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, kCurve);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP2_VERTEX_3);
}

void noCurve(Observations&) {
    glDisable(GL_MAP1_VERTEX_3);
    glDisable(GL_MAP2_VERTEX_3);
}

}  // namespace

std::vector<ApiFunction> objectApiTable() {
    for (std::size_t i = 0; i < sizeof texels; ++i) texels[i] = static_cast<GLubyte>(i * 29 + 3);
    static const GLubyte kListNames[2] = {1, 2};
    static const GLboolean kFlags[3] = {GL_TRUE, GL_FALSE, GL_TRUE};
    static const GLint kIndexArray[3] = {1, 2, 3};
    static const GLfloat kMapF[4] = {0.0f, 0.25f, 0.75f, 1.0f};
    static const GLuint kMapUi[4] = {3, 2, 1, 0};
    static const GLushort kMapUs[2] = {65535, 7};
    // 8 rows of 8 bits, each row padded to the default unpack alignment of 4 bytes.
    static const GLubyte kBitmap[32] = {0xF0, 0, 0, 0, 0x0F, 0, 0, 0, 0xAA, 0, 0, 0, 0x55, 0, 0, 0,
                                        0xFF, 0, 0, 0, 0x81, 0, 0, 0, 0x3C, 0, 0, 0, 0x18, 0, 0, 0};
    return {
        {"glBegin",
         "begin",
         API_CALL(glBegin(GL_TRIANGLES); triangleVertices(); glEnd()),
         {API_CALL(glBegin(kBad)), API_CALL(glBegin(GL_POINTS); glBegin(GL_LINES); glEnd())},
         {},
         true},
        {"glEnd", "begin", API_CALL(glBegin(GL_LINE_LOOP); triangleVertices(); glEnd()), {API_CALL(glEnd())}, {}, true},

        // Display lists.
        {"glGenLists",
         "list",
         [](Observations& o) { o.value("glGenLists(3)", glGenLists(3)); },
         {[](Observations& o) { o.value("glGenLists(-1)", glGenLists(-1)); }},
         {},
         false,
         deleteLists},
        {"glNewList",
         "list",
         API_CALL(rectangleList(20, GL_COMPILE); glCallList(20)),
         {API_CALL(glNewList(0, GL_COMPILE)), API_CALL(glNewList(21, kBad)),
          API_CALL(glNewList(22, GL_COMPILE); glNewList(23, GL_COMPILE); glEndList())},
         listState,
         false,
         deleteLists},
        {"glEndList",
         "list",
         API_CALL(rectangleList(20, GL_COMPILE_AND_EXECUTE)),
         {API_CALL(glEndList())},
         listState,
         false,
         deleteLists},
        {"glCallList",
         "list",
         API_CALL(rectangleList(20, GL_COMPILE); glTranslatef(0.3f, 0.2f, 0.0f); glCallList(20)),
         {},
         listState,
         true,
         deleteLists},
        {"glCallLists",
         "list",
         API_CALL(rectangleList(20, GL_COMPILE); rectangleList(21, GL_COMPILE); glListBase(19);
                  glCallLists(2, GL_UNSIGNED_BYTE, kListNames)),
         {API_CALL(glCallLists(-1, GL_UNSIGNED_BYTE, kListNames)), API_CALL(glCallLists(2, kBad, kListNames))},
         listState,
         true,
         deleteLists},
        {"glDeleteLists",
         "list",
         API_CALL(rectangleList(20, GL_COMPILE); glDeleteLists(20, 1)),
         {API_CALL(glDeleteLists(20, -1))},
         listState,
         false,
         deleteLists},
        {"glIsList",
         "list",
         [](Observations& o) {
             rectangleList(20, GL_COMPILE);
             o.value("glIsList(20)", glIsList(20));
             o.value("glIsList(0)", glIsList(0));
         },
         {},
         {},
         false,
         deleteLists},
        {"glListBase", "list", API_CALL(glListBase(5)), {}, listState, false, deleteLists},

        // Vertex arrays.
        {"glVertexPointer",
         "array",
         API_CALL(glVertexPointer(2, GL_FLOAT, 8, kTriangle)),
         {API_CALL(glVertexPointer(1, GL_FLOAT, 0, kTriangle)), API_CALL(glVertexPointer(5, GL_FLOAT, 0, kTriangle)),
          API_CALL(glVertexPointer(2, kBad, 0, kTriangle)),
          API_CALL(glVertexPointer(2, GL_UNSIGNED_BYTE, 0, kTriangle))},
         arrayState(GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_POINTER, kTriangle,
                    {GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE})},
        {"glColorPointer",
         "array",
         API_CALL(glColorPointer(4, GL_UNSIGNED_BYTE, 0, kColors)),
         {API_CALL(glColorPointer(2, GL_UNSIGNED_BYTE, 0, kColors)), API_CALL(glColorPointer(4, kBad, 0, kColors))},
         arrayState(GL_COLOR_ARRAY, GL_COLOR_ARRAY_POINTER, kColors,
                    {GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE})},
        {"glNormalPointer",
         "array",
         API_CALL(glNormalPointer(GL_FLOAT, 12, kInterleaved)),
         {API_CALL(glNormalPointer(GL_UNSIGNED_BYTE, 0, kInterleaved))},
         arrayState(GL_NORMAL_ARRAY, GL_NORMAL_ARRAY_POINTER, kInterleaved,
                    {GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE})},
        {"glTexCoordPointer",
         "array",
         API_CALL(glTexCoordPointer(3, GL_SHORT, 0, kInterleaved)),
         {API_CALL(glTexCoordPointer(0, GL_SHORT, 0, kInterleaved)),
          API_CALL(glTexCoordPointer(5, GL_SHORT, 0, kInterleaved)),
          API_CALL(glTexCoordPointer(2, GL_UNSIGNED_BYTE, 0, kInterleaved))},
         arrayState(GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_POINTER, kInterleaved,
                    {GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE})},
        {"glEdgeFlagPointer",
         "array",
         API_CALL(glEdgeFlagPointer(1, kFlags)),
         {},
         arrayState(GL_EDGE_FLAG_ARRAY, GL_EDGE_FLAG_ARRAY_POINTER, kFlags, {GL_EDGE_FLAG_ARRAY_STRIDE})},
        {"glIndexPointer",
         "array",
         API_CALL(glIndexPointer(GL_INT, 4, kIndexArray)),
         {API_CALL(glIndexPointer(kBad, 0, kIndexArray))},
         arrayState(GL_INDEX_ARRAY, GL_INDEX_ARRAY_POINTER, kIndexArray, {GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE})},
        // Mesa records GL_INVALID_VALUE for a negative stride and still sets the array (its
        // validate_array reports without failing the call): cases of their own, expected differences.
        {"glVertexPointer:negative_stride",
         "array",
         API_CALL(glVertexPointer(3, GL_FLOAT, 0, kTriangle)),
         {API_CALL(glVertexPointer(2, GL_FLOAT, -1, kTriangle))},
         get({GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_STRIDE})},
        {"glColorPointer:negative_stride",
         "array",
         API_CALL(glColorPointer(3, GL_FLOAT, 0, kTriangle)),
         {API_CALL(glColorPointer(4, GL_UNSIGNED_BYTE, -4, kColors))},
         get({GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_STRIDE})},
        {"glNormalPointer:negative_stride",
         "array",
         API_CALL(glNormalPointer(GL_FLOAT, 0, kTriangle)),
         {API_CALL(glNormalPointer(GL_SHORT, -1, kInterleaved))},
         get({GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE})},
        {"glTexCoordPointer:negative_stride",
         "array",
         API_CALL(glTexCoordPointer(3, GL_FLOAT, 0, kTriangle)),
         {API_CALL(glTexCoordPointer(2, GL_FLOAT, -1, kInterleaved))},
         get({GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_STRIDE})},
        {"glEdgeFlagPointer:negative_stride",
         "array",
         API_CALL(glEdgeFlagPointer(0, kFlags)),
         {API_CALL(glEdgeFlagPointer(-1, kFlags))},
         get({GL_EDGE_FLAG_ARRAY_STRIDE})},
        {"glIndexPointer:negative_stride",
         "array",
         API_CALL(glIndexPointer(GL_INT, 0, kIndexArray)),
         {API_CALL(glIndexPointer(GL_SHORT, -4, kIndexArray))},
         get({GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE})},
        {"glEnableClientState",
         "array",
         API_CALL(glEnableClientState(GL_NORMAL_ARRAY)),
         {API_CALL(glEnableClientState(kBad))},
         get({GL_NORMAL_ARRAY}),
         false,
         disableArrays},
        {"glDisableClientState",
         "array",
         API_CALL(glEnableClientState(GL_EDGE_FLAG_ARRAY); glDisableClientState(GL_EDGE_FLAG_ARRAY)),
         {API_CALL(glDisableClientState(kBad))},
         get({GL_EDGE_FLAG_ARRAY}),
         false,
         disableArrays},
        {"glArrayElement",
         "array",
         API_CALL(vertexArrays(); glBegin(GL_TRIANGLES); glArrayElement(1); glArrayElement(2); glArrayElement(0);
                  glEnd()),
         {},
         get({GL_CURRENT_COLOR}),
         true,
         disableArrays},
        {"glDrawArrays",
         "array",
         API_CALL(vertexArrays(); glDrawArrays(GL_TRIANGLES, 0, 3)),
         {API_CALL(glDrawArrays(kBad, 0, 3)), API_CALL(glDrawArrays(GL_TRIANGLES, 0, -1))},
         get({GL_CURRENT_COLOR}),
         false,
         disableArrays},
        {"glDrawElements",
         "array",
         API_CALL(vertexArrays(); glDrawElements(GL_LINE_LOOP, 3, GL_UNSIGNED_SHORT, kIndices)),
         {API_CALL(glDrawElements(kBad, 3, GL_UNSIGNED_SHORT, kIndices)),
          API_CALL(glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_SHORT, kIndices)),
          notCompiled(API_CALL(glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, kIndices)))},
         get({GL_CURRENT_COLOR}),
         false,
         disableArrays},
        // Compiled into a list, Mesa reports a bad index type as GL_INVALID_VALUE. An expected difference.
        {"glDrawElements:in_list",
         "array",
         API_CALL(vertexArrays(); glDrawElements(GL_POINTS, 3, GL_UNSIGNED_BYTE, kByteIndices)),
         {API_CALL(glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, kIndices))},
         get({GL_CURRENT_COLOR}),
         false,
         disableArrays},
        {"glInterleavedArrays",
         "array",
         API_CALL(glInterleavedArrays(GL_C3F_V3F, 0, kInterleaved); glDrawArrays(GL_TRIANGLES, 0, 3)),
         {API_CALL(glInterleavedArrays(kBad, 0, kInterleaved)),
          API_CALL(glInterleavedArrays(GL_C3F_V3F, -1, kInterleaved))},
         arrayState(
             GL_COLOR_ARRAY, GL_COLOR_ARRAY_POINTER, kInterleaved,
             {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_STRIDE, GL_VERTEX_ARRAY_STRIDE}),
         false,
         disableArrays},
        {"glGetPointerv",
         "array",
         [](Observations& o) {
             glVertexPointer(3, GL_FLOAT, 0, kCurve);
             void* p = nullptr;
             glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
             o.value("pointer is the array", p == kCurve);
         },
         {API_CALL(void* p = nullptr; glGetPointerv(kBad, &p))}},
        {"glPushClientAttrib",
         "array",
         API_CALL(glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS); glPixelStorei(GL_UNPACK_ALIGNMENT, 2)),
         {API_CALL(for (int i = 0; i < 17; ++i) glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT))},
         get({GL_CLIENT_ATTRIB_STACK_DEPTH, GL_UNPACK_ALIGNMENT}),
         false,
         [](Observations& o) {
             popClientAttribs(o);
             glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
         }},
        {"glPopClientAttrib",
         "array",
         API_CALL(glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT); glEnableClientState(GL_COLOR_ARRAY);
                  glPopClientAttrib()),
         {API_CALL(glPopClientAttrib())},
         get({GL_CLIENT_ATTRIB_STACK_DEPTH, GL_COLOR_ARRAY}),
         false,
         popClientAttribs},

        // Pixel rectangles, modes and maps.
        {"glReadPixels",
         "pixels",
         API_CALL(glClearColor(0.3f, 0.5f, 0.7f, 0.9f); glClear(GL_COLOR_BUFFER_BIT);
                  glRectf(-0.5f, -0.5f, 0.0f, 0.0f)),
         {API_CALL(GLubyte b[64]; glReadPixels(0, 0, -1, 2, GL_RGBA, GL_UNSIGNED_BYTE, b)),
          API_CALL(GLubyte b[64]; glReadPixels(0, 0, 2, 2, kBad, GL_UNSIGNED_BYTE, b)),
          API_CALL(GLubyte b[64]; glReadPixels(0, 0, 2, 2, GL_RGBA, kBad, b)),
          API_CALL(GLubyte b[64]; glReadPixels(0, 0, 2, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, b)),
          API_CALL(GLubyte b[64]; glReadPixels(0, 0, 2, 2, GL_RGBA, GL_BITMAP, b))},
         readPixels},
        {"glDrawPixels",
         "pixels",
         API_CALL(rasterAt(-0.5f, -0.25f); glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
         {API_CALL(glDrawPixels(-1, 8, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glDrawPixels(8, 8, kBad, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glDrawPixels(8, 8, GL_RGBA, kBad, texels)),
          API_CALL(glDrawPixels(8, 8, GL_RGBA, GL_BITMAP, texels))},
         readPixels},
        {"glCopyPixels",
         "pixels",
         API_CALL(glRectf(-1.0f, -1.0f, -0.5f, -0.5f); rasterAt(0.0f, 0.0f); glCopyPixels(2, 2, 12, 9, GL_COLOR)),
         {API_CALL(glCopyPixels(0, 0, -1, 4, GL_COLOR)), API_CALL(glCopyPixels(0, 0, 4, 4, kBad))},
         readPixels},
        {"glBitmap",
         "pixels",
         API_CALL(rasterAt(-0.25f, -0.25f); glBitmap(8, 8, 1.5f, 2.0f, 9.0f, -3.0f, kBitmap)),
         {notCompiled(API_CALL(glBitmap(-1, 8, 0, 0, 0, 0, kBitmap))),
          notCompiled(API_CALL(glBitmap(8, -8, 0, 0, 0, 0, kBitmap)))},
         get({GL_CURRENT_RASTER_POSITION})},
        {"glPixelZoom",
         "pixels",
         API_CALL(glPixelZoom(2.0f, -1.5f); rasterAt(-0.5f, 0.5f);
                  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
         {},
         get({GL_ZOOM_X, GL_ZOOM_Y}),
         false,
         resetPixelModes},
        {"glPixelStorei",
         "pixels",
         API_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 2)),
         {API_CALL(glPixelStorei(kBad, 1)), API_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 3)),
          API_CALL(glPixelStorei(GL_UNPACK_ROW_LENGTH, -1))},
         get({GL_PACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH}),
         false,
         resetPixelModes},
        {"glPixelStoref",
         "pixels",
         API_CALL(glPixelStoref(GL_UNPACK_ROW_LENGTH, 3.0f)),
         {API_CALL(glPixelStoref(kBad, 1.0f)), API_CALL(glPixelStoref(GL_UNPACK_SKIP_ROWS, -2.0f))},
         get({GL_UNPACK_ROW_LENGTH}),
         false,
         resetPixelModes},
        {"glPixelTransferf",
         "pixels",
         API_CALL(glPixelTransferf(GL_RED_SCALE, 0.5f)),
         {API_CALL(glPixelTransferf(kBad, 1.0f))},
         get({GL_RED_SCALE}),
         false,
         resetPixelModes},
        {"glPixelTransferi",
         "pixels",
         API_CALL(glPixelTransferi(GL_INDEX_SHIFT, 2)),
         {API_CALL(glPixelTransferi(kBad, 1))},
         get({GL_INDEX_SHIFT}),
         false,
         resetPixelModes},
        {"glPixelMapfv",
         "pixels",
         API_CALL(glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, kMapF)),
         {API_CALL(glPixelMapfv(kBad, 4, kMapF)), API_CALL(glPixelMapfv(GL_PIXEL_MAP_R_TO_R, -1, kMapF)),
          API_CALL(glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 300, kLongF)),
          API_CALL(glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, kMapF))},
         pixelMap(GL_PIXEL_MAP_R_TO_R),
         false,
         resetPixelModes},
        {"glPixelMapuiv",
         "pixels",
         API_CALL(glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, kMapUi)),
         {API_CALL(glPixelMapuiv(kBad, 4, kMapUi)), API_CALL(glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 3, kMapUi))},
         pixelMap(GL_PIXEL_MAP_I_TO_I),
         false,
         resetPixelModes},
        // Mesa's power-of-two check starts at GL_PIXEL_MAP_S_TO_S and misses GL_PIXEL_MAP_I_TO_I
        // (0x0C70, just below): an expected difference.
        {"glPixelMapuiv:i_to_i_size",
         "pixels",
         API_CALL(glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 2, kMapUi)),
         {API_CALL(glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 3, kMapUi))},
         pixelMap(GL_PIXEL_MAP_I_TO_I),
         false,
         resetPixelModes},
        {"glPixelMapusv",
         "pixels",
         API_CALL(glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 2, kMapUs)),
         {API_CALL(glPixelMapusv(kBad, 2, kMapUs)), API_CALL(glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 0, kMapUs))},
         pixelMap(GL_PIXEL_MAP_S_TO_S),
         false,
         resetPixelModes},
        {"glGetPixelMapfv",
         "pixels",
         pixelMap(GL_PIXEL_MAP_G_TO_G),
         {API_CALL(GLfloat f[4]; glGetPixelMapfv(kBad, f))}},
        {"glGetPixelMapuiv",
         "pixels",
         pixelMap(GL_PIXEL_MAP_I_TO_A),
         {API_CALL(GLuint u[4]; glGetPixelMapuiv(kBad, u))}},
        {"glGetPixelMapusv",
         "pixels",
         pixelMap(GL_PIXEL_MAP_A_TO_A),
         {API_CALL(GLushort s[4]; glGetPixelMapusv(kBad, s))}},

        // Selection and feedback.
        {"glSelectBuffer",
         "select",
         [](Observations& o) { selectTriangle(o, [] {}); },
         {API_CALL(glSelectBuffer(-1, selectBuffer)),
          API_CALL(glRenderMode(GL_SELECT); glSelectBuffer(64, selectBuffer); glRenderMode(GL_RENDER))},
         {},
         false,
         renderMode},
        {"glRenderMode",
         "select",
         [](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 glPushName(9);
             });
         },
         {API_CALL(glRenderMode(kBad))},
         get({GL_RENDER_MODE}),
         false,
         renderMode},
        {"glInitNames",
         "select",
         [](Observations& o) {
             selectTriangle(o, [] {
                 glPushName(1);
                 glPushName(2);
                 glInitNames();
                 glPushName(3);
             });
         },
         {},
         {},
         false,
         renderMode},
        {"glPushName",
         "select",
         [](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 glPushName(4);
                 glPushName(5);
             });
         },
         {[](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 for (int i = 0; i < 65; ++i) glPushName(static_cast<GLuint>(i));
             });
         }},
         {},
         false,
         renderMode},
        {"glPopName",
         "select",
         [](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 glPushName(4);
                 glPushName(5);
                 glPopName();
             });
         },
         {[](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 glPopName();
             });
         }},
         {},
         false,
         renderMode},
        {"glLoadName",
         "select",
         [](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 glPushName(4);
                 glLoadName(6);
             });
         },
         {[](Observations& o) {
             selectTriangle(o, [] {
                 glInitNames();
                 glLoadName(6);
             });
         }},
         {},
         false,
         renderMode},
        {"glFeedbackBuffer",
         "select",
         [](Observations& o) {
             std::fill(std::begin(feedbackBuffer), std::end(feedbackBuffer), Observations::kUnwritten);
             glFeedbackBuffer(64, GL_3D_COLOR, feedbackBuffer);
             glRenderMode(GL_FEEDBACK);
             glBegin(GL_TRIANGLES);
             triangleVertices();
             glEnd();
             o.value("values", glRenderMode(GL_RENDER));
             o.floats("feedback", feedbackBuffer, 64);
         },
         {API_CALL(glFeedbackBuffer(-1, GL_3D, feedbackBuffer)), API_CALL(glFeedbackBuffer(64, kBad, feedbackBuffer)),
          API_CALL(glFeedbackBuffer(64, GL_2D, feedbackBuffer); glRenderMode(GL_FEEDBACK);
                   glFeedbackBuffer(64, GL_3D, feedbackBuffer); glRenderMode(GL_RENDER))},
         get({GL_FEEDBACK_BUFFER_SIZE, GL_FEEDBACK_BUFFER_TYPE}),
         false,
         renderMode},
        {"glPassThrough",
         "select",
         [](Observations& o) {
             std::fill(std::begin(feedbackBuffer), std::end(feedbackBuffer), Observations::kUnwritten);
             glFeedbackBuffer(64, GL_2D, feedbackBuffer);
             glRenderMode(GL_FEEDBACK);
             glPassThrough(2.5f);
             o.value("values", glRenderMode(GL_RENDER));
             o.floats("feedback", feedbackBuffer, 64);
         },
         {},
         {},
         false,
         renderMode},

        // Evaluators.
        {"glMap1f",
         "eval",
         API_CALL(glMap1f(GL_MAP1_COLOR_4, 0.0f, 2.0f, 4, 3, kCurve)),
         {notCompiled(API_CALL(glMap1f(kBad, 0.0f, 1.0f, 3, 4, kCurve))),
          API_CALL(glMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 4, kCurve)),
          notCompiled(API_CALL(glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 2, 4, kCurve))),
          API_CALL(glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 0, kCurve)),
          API_CALL(glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 100, kLongF))},
         mapState(GL_MAP1_COLOR_4)},
        {"glMap1d",
         "eval",
         API_CALL(glMap1d(GL_MAP1_VERTEX_3, -1.0, 1.0, 3, 4, kCurveD)),
         {API_CALL(glMap1d(GL_MAP1_VERTEX_3, 0.5, 0.5, 3, 4, kCurveD)),
          notCompiled(API_CALL(glMap1d(kBad, 0.0, 1.0, 3, 4, kCurveD)))},
         mapState(GL_MAP1_VERTEX_3)},
        {"glMap2f",
         "eval",
         API_CALL(glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 3, 0.0f, 2.0f, 6, 2, kCurve)),
         {API_CALL(glMap2f(kBad, 0.0f, 1.0f, 2, 3, 0.0f, 2.0f, 6, 2, kCurve)),
          API_CALL(glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 3, 1.0f, 1.0f, 6, 2, kCurve)),
          notCompiled(API_CALL(glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 3, 0.0f, 1.0f, 1, 2, kCurve))),
          API_CALL(glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 3, 0.0f, 1.0f, 6, 0, kCurve))},
         mapState(GL_MAP2_TEXTURE_COORD_2)},
        // Compiled into a list, Mesa copies the control points packed and runs the map with the
        // packed strides: a stride too small is no error and defines the map; a bad target
        // (no components) is GL_INVALID_VALUE. An expected difference.
        {"glMap1f:in_list",
         "eval",
         API_CALL(glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, kCurve)),
         {API_CALL(glMap1f(kBad, 0.0f, 1.0f, 3, 4, kCurve)),
          API_CALL(glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 2, 4, kCurve)),
          API_CALL(glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 3, 0.0f, 1.0f, 1, 2, kCurve))},
         mapState(GL_MAP1_VERTEX_3)},
        {"glMap2d",
         "eval",
         API_CALL(glMap2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 2, kCurveD)),
         {API_CALL(glMap2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 99, kLongD)),
          API_CALL(glMap2d(kBad, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 2, kCurveD)),
          API_CALL(glMap2d(GL_MAP2_VERTEX_3, 0.0, 0.0, 3, 2, 0.0, 1.0, 6, 2, kCurveD))},
         mapState(GL_MAP2_VERTEX_3)},
        {"glMapGrid1f",
         "eval",
         API_CALL(glMapGrid1f(10, 0.25f, 0.75f)),
         {API_CALL(glMapGrid1f(0, 0.0f, 1.0f))},
         get({GL_MAP1_GRID_DOMAIN, GL_MAP1_GRID_SEGMENTS})},
        {"glMapGrid1d",
         "eval",
         API_CALL(glMapGrid1d(6, 1.0, -1.0)),
         {API_CALL(glMapGrid1d(-1, 0.0, 1.0))},
         get({GL_MAP1_GRID_DOMAIN, GL_MAP1_GRID_SEGMENTS})},
        {"glMapGrid2f",
         "eval",
         API_CALL(glMapGrid2f(3, 0.0f, 1.0f, 5, 0.5f, 1.0f)),
         {API_CALL(glMapGrid2f(0, 0.0f, 1.0f, 5, 0.0f, 1.0f)), API_CALL(glMapGrid2f(3, 0.0f, 1.0f, -5, 0.0f, 1.0f))},
         get({GL_MAP2_GRID_DOMAIN, GL_MAP2_GRID_SEGMENTS})},
        {"glMapGrid2d",
         "eval",
         API_CALL(glMapGrid2d(4, 0.0, 1.0, 2, 1.0, 0.0)),
         {API_CALL(glMapGrid2d(4, 0.0, 1.0, 0, 0.0, 1.0))},
         get({GL_MAP2_GRID_DOMAIN, GL_MAP2_GRID_SEGMENTS})},
        {"glEvalMesh1",
         "eval",
         API_CALL(curve(); glMapGrid1f(12, 0.0f, 1.0f); glEvalMesh1(GL_LINE, 0, 12)),
         {API_CALL(glEvalMesh1(GL_FILL, 0, 12)), API_CALL(glEvalMesh1(kBad, 0, 12))},
         {},
         false,
         noCurve},
        {"glEvalMesh2",
         "eval",
         API_CALL(curve(); glMapGrid2f(4, 0.0f, 1.0f, 4, 0.0f, 1.0f); glEvalMesh2(GL_FILL, 0, 4, 0, 4)),
         {API_CALL(glEvalMesh2(kBad, 0, 4, 0, 4))},
         {},
         false,
         noCurve},
        {"glGetMapdv",
         "eval",
         mapState(GL_MAP1_NORMAL),
         {API_CALL(GLdouble d[4]; glGetMapdv(kBad, GL_ORDER, d)),
          API_CALL(GLdouble d[4]; glGetMapdv(GL_MAP1_NORMAL, kBad, d))}},
        {"glGetMapfv",
         "eval",
         mapState(GL_MAP2_INDEX),
         {API_CALL(GLfloat f[4]; glGetMapfv(kBad, GL_DOMAIN, f)),
          API_CALL(GLfloat f[4]; glGetMapfv(GL_MAP2_INDEX, kBad, f))}},
        {"glGetMapiv",
         "eval",
         mapState(GL_MAP1_TEXTURE_COORD_4),
         {API_CALL(GLint i[4]; glGetMapiv(GL_MAP1_VERTEX_4, kBad, i)),
          API_CALL(GLint i[4]; glGetMapiv(kBad, GL_ORDER, i))}},
    };
}

}  // namespace conformance
