// The API table's per-vertex functions: the calls allowed between glBegin and glEnd (no error of
// their own) and the ones drawing at once (glRasterPos, glRect: an error inside glBegin/glEnd).
#include <glad/gl.h>

#include "api_table.h"

namespace conformance {
namespace {

// Values of each type, chosen away from the ends so that every conversion shows.
const GLbyte kB[4] = {10, -20, 127, 64};
const GLubyte kUb[4] = {10, 200, 255, 64};
const GLshort kS[4] = {1000, -2000, 32767, 64};
const GLushort kUs[4] = {1000, 60000, 65535, 64};
const GLint kI[4] = {100000, -2000000000, 2147483647, 64};
const GLuint kUi[4] = {100000, 4000000000u, 4294967295u, 64};
const GLfloat kF[4] = {0.25f, 0.5f, 0.75f, 0.125f};
const GLdouble kD[4] = {0.3, 0.6, 0.1, 0.9};
// Vertex positions and texture coordinates small enough to land in the window.
const GLshort kSmallS[4] = {0, 0, 0, 1};
const GLint kSmallI[4] = {0, 0, 0, 1};
const GLfloat kPos[4] = {0.25f, -0.5f, 0.0f, 1.0f};
const GLdouble kPosD[4] = {-0.375, 0.25, 0.5, 1.0};

// A point drawn through the vertex call `call`.
// clang-format off
#define VERTEX(fn, ...) \
    ApiFunction{#fn, "vertex", [](Observations&) { glBegin(GL_POINTS); fn(__VA_ARGS__); glEnd(); }, {}, {}, true}
// clang-format on
// A current attribute set by `fn`, read back with glGetFloatv(pname).
// clang-format off
#define CURRENT(group, pname, name, fn, ...) \
    ApiFunction{name, group, [](Observations&) { fn(__VA_ARGS__); }, {}, [](Observations& o) { o.get({pname}); }, true}
// clang-format on
#define COLOR(fn, ...) CURRENT("color", GL_CURRENT_COLOR, #fn, fn, __VA_ARGS__)
#define NORMAL(fn, ...) CURRENT("normal", GL_CURRENT_NORMAL, #fn, fn, __VA_ARGS__)
#define TEXCOORD(fn, ...) CURRENT("texcoord", GL_CURRENT_TEXTURE_COORDS, #fn, fn, __VA_ARGS__)
#define INDEX(fn, ...) CURRENT("index", GL_CURRENT_INDEX, #fn, fn, __VA_ARGS__)
// A raster position: an error inside glBegin/glEnd, read back with its validity; a bitmap
// drawn there shows it in pixels.
// clang-format off
#define RASTERPOS(fn, ...)                                                                      \
    ApiFunction{#fn, "rasterpos", [](Observations&) { fn(__VA_ARGS__); }, {}, [](Observations& o) { \
                    o.get({GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_POSITION_VALID});        \
                    const GLubyte block[8] = {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};   \
                    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);                                        \
                    glBitmap(3, 8, 0, 0, 0, 0, block);                                            \
                    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);                                        \
                }}
// clang-format on
#define RECT(fn, ...)                                       \
    ApiFunction {                                           \
#fn, "rect", [](Observations&) { fn(__VA_ARGS__); } \
    }

const GLfloat kCurve[3][3] = {{-0.8f, -0.6f, 0.0f}, {0.0f, 0.9f, 0.2f}, {0.8f, -0.5f, 0.0f}};
const GLfloat kPatch[2][2][3] = {{{-0.7f, -0.7f, 0.0f}, {0.7f, -0.6f, 0.1f}},
                                 {{-0.6f, 0.7f, 0.2f}, {0.6f, 0.8f, 0.0f}}};

// An evaluator call between glBegin(GL_POINTS) and glEnd with a curve (dims 1) or patch enabled.
template <int Dims, class Call>
void evaluate(Call call) {
    if (Dims == 1) {
        glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 3, &kCurve[0][0]);
        glMapGrid1f(8, 0.0f, 1.0f);
    } else {
        glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &kPatch[0][0][0]);
        glMapGrid2f(4, 0.0f, 1.0f, 4, 0.0f, 1.0f);
    }
    const GLenum map = Dims == 1 ? GL_MAP1_VERTEX_3 : GL_MAP2_VERTEX_3;
    glEnable(map);
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    call();
    glEnd();
    glPointSize(1.0f);
    glDisable(map);
}
// clang-format off
#define EVAL(dims, fn, ...) \
    ApiFunction{#fn, "eval", [](Observations&) { evaluate<dims>([] { fn(__VA_ARGS__); }); }, {}, {}, true}
// clang-format on

}  // namespace

std::vector<ApiFunction> vertexApiTable() {
    static const GLdouble e1d[1] = {0.25}, e2d[2] = {0.25, 0.75};
    static const GLfloat e1f[1] = {0.75f}, e2f[2] = {0.5f, 0.125f};
    static const GLboolean flag = GL_FALSE;
    return {
        VERTEX(glVertex2d, 0.3, 0.4),
        VERTEX(glVertex2dv, kPosD),
        VERTEX(glVertex2f, 0.5f, -0.25f),
        VERTEX(glVertex2fv, kPos),
        VERTEX(glVertex2i, 0, 0),
        VERTEX(glVertex2iv, kSmallI),
        VERTEX(glVertex2s, 0, 0),
        VERTEX(glVertex2sv, kSmallS),
        VERTEX(glVertex3d, -0.3, 0.4, 0.5),
        VERTEX(glVertex3dv, kPosD),
        VERTEX(glVertex3f, 0.5f, 0.75f, -0.5f),
        VERTEX(glVertex3fv, kPos),
        VERTEX(glVertex3i, 0, 0, 0),
        VERTEX(glVertex3iv, kSmallI),
        VERTEX(glVertex3s, 0, 0, 0),
        VERTEX(glVertex3sv, kSmallS),
        VERTEX(glVertex4d, 0.3, 0.4, 0.0, 2.0),
        VERTEX(glVertex4dv, kPosD),
        VERTEX(glVertex4f, -0.5f, -0.5f, 0.0f, 0.5f),
        VERTEX(glVertex4fv, kPos),
        VERTEX(glVertex4i, 0, 0, 0, 1),
        VERTEX(glVertex4iv, kSmallI),
        VERTEX(glVertex4s, 0, 0, 0, 2),
        VERTEX(glVertex4sv, kSmallS),

        COLOR(glColor3b, 10, -20, 127),
        COLOR(glColor3bv, kB),
        COLOR(glColor3d, 0.3, 0.6, 0.1),
        COLOR(glColor3dv, kD),
        COLOR(glColor3f, 0.25f, 1.5f, -0.5f),
        COLOR(glColor3fv, kF),
        COLOR(glColor3i, 100000, -2000000000, 2147483647),
        COLOR(glColor3iv, kI),
        COLOR(glColor3s, 1000, -2000, 32767),
        COLOR(glColor3sv, kS),
        COLOR(glColor3ub, 10, 200, 255),
        COLOR(glColor3ubv, kUb),
        COLOR(glColor3ui, 100000, 4000000000u, 4294967295u),
        COLOR(glColor3uiv, kUi),
        COLOR(glColor3us, 1000, 60000, 65535),
        COLOR(glColor3usv, kUs),
        COLOR(glColor4b, 10, -20, 127, 64),
        COLOR(glColor4bv, kB),
        COLOR(glColor4d, 0.3, 0.6, 0.1, 0.9),
        COLOR(glColor4dv, kD),
        COLOR(glColor4f, 0.25f, 0.5f, 0.75f, 0.125f),
        COLOR(glColor4fv, kF),
        COLOR(glColor4i, 100000, -2000000000, 2147483647, 64),
        COLOR(glColor4iv, kI),
        COLOR(glColor4s, 1000, -2000, 32767, 64),
        COLOR(glColor4sv, kS),
        COLOR(glColor4ub, 10, 200, 255, 64),
        COLOR(glColor4ubv, kUb),
        COLOR(glColor4ui, 100000, 4000000000u, 4294967295u, 64),
        COLOR(glColor4uiv, kUi),
        COLOR(glColor4us, 1000, 60000, 65535, 64),
        COLOR(glColor4usv, kUs),

        NORMAL(glNormal3b, 10, -20, 127),
        NORMAL(glNormal3bv, kB),
        NORMAL(glNormal3d, 0.3, 0.6, 0.1),
        NORMAL(glNormal3dv, kD),
        NORMAL(glNormal3f, 0.25f, 1.5f, -0.5f),
        NORMAL(glNormal3fv, kF),
        NORMAL(glNormal3i, 100000, -2000000000, 2147483647),
        NORMAL(glNormal3iv, kI),
        NORMAL(glNormal3s, 1000, -2000, 32767),
        NORMAL(glNormal3sv, kS),

        TEXCOORD(glTexCoord1d, 0.3),
        TEXCOORD(glTexCoord1dv, kD),
        TEXCOORD(glTexCoord1f, 0.25f),
        TEXCOORD(glTexCoord1fv, kF),
        TEXCOORD(glTexCoord1i, 7),
        TEXCOORD(glTexCoord1iv, kI),
        TEXCOORD(glTexCoord1s, -3),
        TEXCOORD(glTexCoord1sv, kS),
        TEXCOORD(glTexCoord2d, 0.3, 0.6),
        TEXCOORD(glTexCoord2dv, kD),
        TEXCOORD(glTexCoord2f, 0.25f, 1.5f),
        TEXCOORD(glTexCoord2fv, kF),
        TEXCOORD(glTexCoord2i, 7, -8),
        TEXCOORD(glTexCoord2iv, kI),
        TEXCOORD(glTexCoord2s, -3, 4),
        TEXCOORD(glTexCoord2sv, kS),
        TEXCOORD(glTexCoord3d, 0.3, 0.6, 0.1),
        TEXCOORD(glTexCoord3dv, kD),
        TEXCOORD(glTexCoord3f, 0.25f, 1.5f, -0.5f),
        TEXCOORD(glTexCoord3fv, kF),
        TEXCOORD(glTexCoord3i, 7, -8, 9),
        TEXCOORD(glTexCoord3iv, kI),
        TEXCOORD(glTexCoord3s, -3, 4, 5),
        TEXCOORD(glTexCoord3sv, kS),
        TEXCOORD(glTexCoord4d, 0.3, 0.6, 0.1, 2.0),
        TEXCOORD(glTexCoord4dv, kD),
        TEXCOORD(glTexCoord4f, 0.25f, 1.5f, -0.5f, 0.5f),
        TEXCOORD(glTexCoord4fv, kF),
        TEXCOORD(glTexCoord4i, 7, -8, 9, 2),
        TEXCOORD(glTexCoord4iv, kI),
        TEXCOORD(glTexCoord4s, -3, 4, 5, 6),
        TEXCOORD(glTexCoord4sv, kS),

        INDEX(glIndexd, 3.75),
        INDEX(glIndexdv, kD),
        INDEX(glIndexf, 12.5f),
        INDEX(glIndexfv, kF),
        INDEX(glIndexi, 300),
        INDEX(glIndexiv, kI),
        INDEX(glIndexs, -7),
        INDEX(glIndexsv, kS),
        INDEX(glIndexub, 200),
        INDEX(glIndexubv, kUb),

        CURRENT("edgeflag", GL_EDGE_FLAG, "glEdgeFlag", glEdgeFlag, GL_FALSE),
        CURRENT("edgeflag", GL_EDGE_FLAG, "glEdgeFlagv", glEdgeFlagv, &flag),

        RASTERPOS(glRasterPos2d, 0.3, 0.4),
        RASTERPOS(glRasterPos2dv, kPosD),
        RASTERPOS(glRasterPos2f, 0.5f, -0.25f),
        RASTERPOS(glRasterPos2fv, kPos),
        RASTERPOS(glRasterPos2i, 0, 0),
        RASTERPOS(glRasterPos2iv, kSmallI),
        RASTERPOS(glRasterPos2s, 0, 0),
        RASTERPOS(glRasterPos2sv, kSmallS),
        RASTERPOS(glRasterPos3d, -0.3, 0.4, 0.5),
        RASTERPOS(glRasterPos3dv, kPosD),
        RASTERPOS(glRasterPos3f, 0.5f, 0.75f, -2.0f),
        RASTERPOS(glRasterPos3fv, kPos),
        RASTERPOS(glRasterPos3i, 0, 0, 0),
        RASTERPOS(glRasterPos3iv, kSmallI),
        RASTERPOS(glRasterPos3s, 0, 0, 0),
        RASTERPOS(glRasterPos3sv, kSmallS),
        RASTERPOS(glRasterPos4d, 0.3, 0.4, 0.0, 2.0),
        RASTERPOS(glRasterPos4dv, kPosD),
        RASTERPOS(glRasterPos4f, -0.5f, -0.5f, 0.0f, 0.5f),
        RASTERPOS(glRasterPos4fv, kPos),
        RASTERPOS(glRasterPos4i, 0, 0, 0, 1),
        RASTERPOS(glRasterPos4iv, kSmallI),
        RASTERPOS(glRasterPos4s, 0, 0, 0, 2),
        RASTERPOS(glRasterPos4sv, kSmallS),

        RECT(glRectd, -0.5, -0.25, 0.25, 0.5),
        RECT(glRectdv, &kPosD[0], &kPosD[2]),
        RECT(glRectf, 0.5f, 0.5f, -0.25f, -0.75f),
        RECT(glRectfv, &kPos[0], &kPos[2]),
        RECT(glRecti, -1, -1, 0, 0),
        RECT(glRectiv, &kSmallI[0], &kSmallI[2]),
        RECT(glRects, 0, 0, 1, 1),
        RECT(glRectsv, &kSmallS[0], &kSmallS[2]),

        EVAL(1, glEvalCoord1d, 0.25),
        EVAL(1, glEvalCoord1dv, e1d),
        EVAL(1, glEvalCoord1f, 0.75f),
        EVAL(1, glEvalCoord1fv, e1f),
        EVAL(2, glEvalCoord2d, 0.25, 0.75),
        EVAL(2, glEvalCoord2dv, e2d),
        EVAL(2, glEvalCoord2f, 0.5f, 0.125f),
        EVAL(2, glEvalCoord2fv, e2f),
        EVAL(1, glEvalPoint1, 3),
        EVAL(2, glEvalPoint2, 1, 3),
    };
}

}  // namespace conformance
