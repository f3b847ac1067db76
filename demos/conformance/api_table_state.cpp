// The API table's state functions: enables, rasterization modes, matrices, lighting, fog, the
// per-fragment operations and buffers, the attribute stack and the plain queries.
#include <glad/gl.h>

#include <algorithm>
#include <string>

#include "api_table.h"

namespace conformance {
namespace {

constexpr GLenum kBad = kBadEnum;

// glGetLightfv/iv and glGetMaterialfv/iv answers.
ApiCall light(GLenum l, GLenum pname) {
    return [l, pname](Observations& o) {
        o.floatsAndInts(
            "glGetLight", [&](GLfloat* v) { glGetLightfv(l, pname, v); }, [&](GLint* v) { glGetLightiv(l, pname, v); });
    };
}
ApiCall material(GLenum face, GLenum pname) {
    return [face, pname](Observations& o) {
        o.floatsAndInts(
            "glGetMaterial", [&](GLfloat* v) { glGetMaterialfv(face, pname, v); },
            [&](GLint* v) { glGetMaterialiv(face, pname, v); });
    };
}

// A matrix call's effect on the modelview matrix, drawn with a triangle too.
ApiCall modelview() {
    return [](Observations& o) {
        o.get({GL_MODELVIEW_MATRIX, GL_MODELVIEW_STACK_DEPTH});
        glBegin(GL_TRIANGLES);
        glVertex2f(-0.5f, -0.5f);
        glVertex2f(0.5f, -0.4f);
        glVertex2f(0.0f, 0.5f);
        glEnd();
    };
}

void popAllMatrices() {
    for (GLenum mode : {GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE}) {
        glMatrixMode(mode);
        for (int i = 0; i < 40; ++i) glPopMatrix();
        glLoadIdentity();
    }
    glMatrixMode(GL_MODELVIEW);
}

void popAllAttribs() {
    for (int i = 0; i < 20; ++i) glPopAttrib();
}

// A triangle under the state a row leaves, for the pixels.
void triangle(Observations&) {
    glBegin(GL_TRIANGLES);
    glColor4f(0.8f, 0.4f, 0.2f, 0.5f);
    glVertex3f(-0.7f, -0.6f, 0.3f);
    glVertex3f(0.7f, -0.5f, -0.2f);
    glVertex3f(0.0f, 0.7f, 0.1f);
    glEnd();
    glColor4f(1, 1, 1, 1);
}

// The effect of a row: its queries, then a triangle drawn under the state.
ApiCall drawn(std::vector<unsigned> pnames) {
    return [q = get(std::move(pnames))](Observations& o) {
        q(o);
        triangle(o);
    };
}

// glGetBooleanv, glGetDoublev, glGetIntegerv of `pname`, into 16 values marked unwritten.
ApiCall getBooleans(GLenum pname) {
    return [pname](Observations& o) {
        GLboolean b[16];
        std::fill(std::begin(b), std::end(b), GLubyte{0xA5});
        glGetBooleanv(pname, b);
        o.bytes("glGetBooleanv", b, 16);
    };
}
ApiCall getDoubles(GLenum pname) {
    return [pname](Observations& o) {
        GLdouble d[16];
        std::fill(std::begin(d), std::end(d), Observations::kUnwritten);
        glGetDoublev(pname, d);
        o.doubles("glGetDoublev", d, 16);
    };
}
ApiCall getIntegers(GLenum pname) {
    return [pname](Observations& o) {
        GLint v[16];
        std::fill(std::begin(v), std::end(v), static_cast<GLint>(Observations::kUnwritten));
        glGetIntegerv(pname, v);
        o.ints("glGetIntegerv", v, 16);
    };
}
ApiCall clipPlane(GLenum plane) {
    return [plane](Observations& o) {
        GLdouble eq[4] = {-1, -1, -1, -1};
        glGetClipPlane(plane, eq);
        o.doubles("glGetClipPlane", eq, 4);
    };
}

const GLdouble kMatrixD[16] = {1, 0.5, 0, 0, -0.25, 1, 0, 0, 0, 0, 1, 0, 0.125, -0.25, 0, 1};
const GLfloat kMatrixF[16] = {0.5f, 0, 0, 0, 0, 0.75f, 0, 0, 0, 0, 1, 0, 0.25f, 0.125f, 0, 1};
const GLfloat kColor[4] = {0.2f, 0.4f, 0.6f, 0.8f};
const GLint kColorI[4] = {1073741823, -1073741824, 2147483647, 0};
const GLfloat kPosition[4] = {1.0f, 2.0f, 3.0f, 0.0f};
const GLdouble kPlane[4] = {1.0, -0.5, 0.0, 0.25};
GLubyte stipple[128];

}  // namespace

ApiCall get(std::vector<unsigned> pnames) {
    return [pnames](Observations& o) {
        for (unsigned p : pnames) o.get({p});
    };
}

std::vector<ApiFunction> stateApiTable() {
    for (int i = 0; i < 128; ++i) stipple[i] = static_cast<GLubyte>(i * 37 + 11);
    return {
        // Enables and plain queries.
        {"glEnable",
         "enable",
         API_CALL(glEnable(GL_CULL_FACE)),
         {API_CALL(glEnable(kBad)), API_CALL(glEnable(GL_TRIANGLES))},
         get({GL_CULL_FACE})},
        {"glDisable",
         "enable",
         API_CALL(glEnable(GL_DITHER); glDisable(GL_DITHER)),
         {API_CALL(glDisable(kBad))},
         get({GL_DITHER}),
         false,
         API_CALL(glEnable(GL_DITHER))},
        {"glIsEnabled",
         "enable",
         [](Observations& o) { o.value("glIsEnabled(GL_DITHER)", glIsEnabled(GL_DITHER)); },
         {[](Observations& o) { o.value("glIsEnabled(bad)", glIsEnabled(kBad)); }}},
        {"glGetBooleanv", "query", getBooleans(GL_COLOR_WRITEMASK), {getBooleans(kBad)}},
        {"glGetDoublev", "query", getDoubles(GL_DEPTH_RANGE), {getDoubles(kBad)}},
        {"glGetFloatv", "query", get({GL_COLOR_CLEAR_VALUE}), {get({kBad})}},
        {"glGetIntegerv", "query", getIntegers(GL_VIEWPORT), {getIntegers(kBad)}},
        // Mesa converts a matrix's elements as normalized values (1 gives INT_MAX); the spec
        // rounds them. An expected difference.
        {"glGetIntegerv:matrix", "query",
         [](Observations& o) {
             glScalef(2.0f, 0.5f, 1.0f);
             getIntegers(GL_MODELVIEW_MATRIX)(o);
         }},
        // glGetError inside glBegin/glEnd is itself the error (answering 0 there).
        {"glGetError", "query", [](Observations& o) { o.value("glGetError", glGetError()); }},
        // The strings differ between implementations: whether there is one is compared.
        {"glGetString",
         "query",
         [](Observations& o) {
             for (GLenum name : {GL_VENDOR, GL_RENDERER, GL_VERSION, GL_EXTENSIONS})
                 o.value("glGetString non-null", glGetString(name) != nullptr);
         },
         {[](Observations& o) { o.value("glGetString(bad) non-null", glGetString(kBad) != nullptr); }}},
        {"glHint",
         "enable",
         API_CALL(glHint(GL_FOG_HINT, GL_NICEST)),
         {API_CALL(glHint(kBad, GL_NICEST)), API_CALL(glHint(GL_FOG_HINT, kBad))},
         get({GL_FOG_HINT})},
        {"glFinish", "enable", API_CALL(glFinish())},
        {"glFlush", "enable", API_CALL(glFlush())},

        // Rasterization modes.
        {"glCullFace",
         "raster",
         API_CALL(glCullFace(GL_FRONT)),
         {API_CALL(glCullFace(kBad)), API_CALL(glCullFace(GL_LINE))},
         drawn({GL_CULL_FACE_MODE})},
        {"glFrontFace", "raster", API_CALL(glFrontFace(GL_CW)), {API_CALL(glFrontFace(kBad))}, drawn({GL_FRONT_FACE})},
        {"glShadeModel",
         "raster",
         API_CALL(glShadeModel(GL_FLAT)),
         {API_CALL(glShadeModel(kBad))},
         drawn({GL_SHADE_MODEL})},
        {"glPolygonMode",
         "raster",
         API_CALL(glPolygonMode(GL_FRONT, GL_LINE)),
         {API_CALL(glPolygonMode(kBad, GL_LINE)), API_CALL(glPolygonMode(GL_FRONT, kBad)),
          API_CALL(glPolygonMode(GL_FRONT, GL_FRONT))},
         drawn({GL_POLYGON_MODE})},
        {"glPolygonOffset",
         "raster",
         API_CALL(glPolygonOffset(1.5f, -2.0f)),
         {},
         get({GL_POLYGON_OFFSET_FACTOR, GL_POLYGON_OFFSET_UNITS})},
        {"glPolygonStipple",
         "raster",
         API_CALL(glPolygonStipple(stipple); glEnable(GL_POLYGON_STIPPLE)),
         {},
         [](Observations& o) {
             GLubyte back[128];
             std::fill(std::begin(back), std::end(back), GLubyte{0xA5});
             glGetPolygonStipple(back);
             o.bytes("glGetPolygonStipple", back, 128);
             triangle(o);
         },
         false,
         API_CALL(glDisable(GL_POLYGON_STIPPLE))},
        {"glGetPolygonStipple", "raster",
         [](Observations& o) {
             GLubyte back[128];
             std::fill(std::begin(back), std::end(back), GLubyte{0xA5});
             glGetPolygonStipple(back);
             o.bytes("glGetPolygonStipple", back, 128);
         }},
        {"glLineStipple",
         "raster",
         API_CALL(glLineStipple(3, 0xF0F0)),
         {},
         get({GL_LINE_STIPPLE_REPEAT, GL_LINE_STIPPLE_PATTERN})},
        {"glLineWidth",
         "raster",
         API_CALL(glLineWidth(2.5f)),
         {API_CALL(glLineWidth(0.0f)), API_CALL(glLineWidth(-1.0f))},
         get({GL_LINE_WIDTH}),
         false,
         API_CALL(glLineWidth(1.0f))},
        {"glPointSize",
         "raster",
         API_CALL(glPointSize(4.0f)),
         {API_CALL(glPointSize(0.0f)), API_CALL(glPointSize(-2.0f))},
         get({GL_POINT_SIZE}),
         false,
         API_CALL(glPointSize(1.0f))},
        {"glViewport",
         "raster",
         API_CALL(glViewport(4, 6, 40, 30)),
         {API_CALL(glViewport(0, 0, -1, 10)), API_CALL(glViewport(0, 0, 10, -1))},
         drawn({GL_VIEWPORT})},
        {"glClipPlane",
         "raster",
         API_CALL(glClipPlane(GL_CLIP_PLANE2, kPlane); glEnable(GL_CLIP_PLANE2)),
         {API_CALL(glClipPlane(kBad, kPlane)), API_CALL(glClipPlane(GL_CLIP_PLANE0 + 8, kPlane))},
         [](Observations& o) {
             clipPlane(GL_CLIP_PLANE2)(o);
             triangle(o);
         },
         false,
         API_CALL(glDisable(GL_CLIP_PLANE2))},
        {"glGetClipPlane", "raster", clipPlane(GL_CLIP_PLANE0), {clipPlane(kBad)}},

        // Matrices.
        {"glMatrixMode",
         "matrix",
         API_CALL(glMatrixMode(GL_TEXTURE)),
         {API_CALL(glMatrixMode(kBad))},
         get({GL_MATRIX_MODE}),
         false,
         API_CALL(glMatrixMode(GL_MODELVIEW))},
        {"glLoadIdentity", "matrix", API_CALL(glTranslatef(1, 2, 3); glLoadIdentity()), {}, modelview()},
        {"glLoadMatrixd", "matrix", API_CALL(glLoadMatrixd(kMatrixD)), {}, modelview()},
        {"glLoadMatrixf", "matrix", API_CALL(glLoadMatrixf(kMatrixF)), {}, modelview()},
        {"glMultMatrixd", "matrix", API_CALL(glMultMatrixd(kMatrixD)), {}, modelview()},
        {"glMultMatrixf", "matrix", API_CALL(glMultMatrixf(kMatrixF)), {}, modelview()},
        {"glRotated", "matrix", API_CALL(glRotated(30.0, 0.0, 0.0, 1.0)), {}, modelview()},
        {"glRotatef", "matrix", API_CALL(glRotatef(-45.0f, 1.0f, 1.0f, 1.0f)), {}, modelview()},
        {"glScaled", "matrix", API_CALL(glScaled(0.5, 0.75, 2.0)), {}, modelview()},
        {"glScalef", "matrix", API_CALL(glScalef(1.25f, -0.5f, 1.0f)), {}, modelview()},
        {"glTranslated", "matrix", API_CALL(glTranslated(0.25, -0.125, 0.0)), {}, modelview()},
        {"glTranslatef", "matrix", API_CALL(glTranslatef(-0.25f, 0.375f, 0.5f)), {}, modelview()},
        {"glFrustum",
         "matrix",
         API_CALL(glMatrixMode(GL_PROJECTION); glFrustum(-1, 1, -1, 1, 1, 10); glMatrixMode(GL_MODELVIEW)),
         {API_CALL(glFrustum(-1, 1, -1, 1, 0, 10)), API_CALL(glFrustum(-1, 1, -1, 1, -1, 10)),
          API_CALL(glFrustum(1, 1, -1, 1, 1, 10)), API_CALL(glFrustum(-1, 1, 2, 2, 1, 10)),
          API_CALL(glFrustum(-1, 1, -1, 1, 5, 5))},
         get({GL_PROJECTION_MATRIX, GL_MODELVIEW_MATRIX})},
        {"glOrtho",
         "matrix",
         API_CALL(glOrtho(-2, 2, -1.5, 1.5, -1, 1)),
         {API_CALL(glOrtho(1, 1, -1, 1, -1, 1)), API_CALL(glOrtho(-1, 1, 3, 3, -1, 1)),
          API_CALL(glOrtho(-1, 1, -1, 1, 2, 2))},
         modelview()},
        {"glPushMatrix",
         "matrix",
         API_CALL(glPushMatrix(); glTranslatef(0.5f, 0, 0)),
         {API_CALL(for (int i = 0; i < 33; ++i) glPushMatrix())},
         modelview(),
         false,
         API_CALL(popAllMatrices())},
        {"glPopMatrix",
         "matrix",
         API_CALL(glPushMatrix(); glTranslatef(0.5f, 0, 0); glPopMatrix()),
         {API_CALL(glPopMatrix()), API_CALL(glMatrixMode(GL_PROJECTION); glPopMatrix(); glMatrixMode(GL_MODELVIEW))},
         modelview(),
         false,
         API_CALL(popAllMatrices())},

        // Lighting.
        {"glLightf",
         "lighting",
         API_CALL(glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 10.0f)),
         {API_CALL(glLightf(kBad, GL_SPOT_EXPONENT, 1.0f)), API_CALL(glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1.0f)),
          API_CALL(glLightf(GL_LIGHT1, kBad, 1.0f)), API_CALL(glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 129.0f)),
          API_CALL(glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, -1.0f)), API_CALL(glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 91.0f)),
          API_CALL(glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, -1.0f))},
         light(GL_LIGHT1, GL_SPOT_EXPONENT),
         false,
         API_CALL(glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 0.0f))},
        {"glLighti",
         "lighting",
         API_CALL(glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 45)),
         {API_CALL(glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, -5)), API_CALL(glLighti(GL_LIGHT2, GL_LINEAR_ATTENUATION, -1)),
          API_CALL(glLighti(GL_LIGHT2, kBad, 1)), API_CALL(glLighti(kBad, GL_SPOT_CUTOFF, 45))},
         light(GL_LIGHT2, GL_SPOT_CUTOFF),
         false,
         API_CALL(glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 180))},
        {"glLightfv",
         "lighting",
         API_CALL(glLightfv(GL_LIGHT3, GL_POSITION, kPosition)),
         {API_CALL(glLightfv(kBad, GL_POSITION, kPosition)), API_CALL(glLightfv(GL_LIGHT3, kBad, kPosition))},
         light(GL_LIGHT3, GL_POSITION)},
        {"glLightiv",
         "lighting",
         API_CALL(glLightiv(GL_LIGHT4, GL_DIFFUSE, kColorI)),
         {API_CALL(glLightiv(GL_LIGHT4, kBad, kColorI)), API_CALL(glLightiv(GL_LIGHT0 + 9, GL_DIFFUSE, kColorI))},
         light(GL_LIGHT4, GL_DIFFUSE)},
        {"glGetLightfv",
         "lighting",
         light(GL_LIGHT0, GL_SPECULAR),
         {[](Observations&) {
              GLfloat f[4];
              glGetLightfv(kBad, GL_AMBIENT, f);
          },
          [](Observations&) {
              GLfloat f[4];
              glGetLightfv(GL_LIGHT0, kBad, f);
          }}},
        {"glGetLightiv",
         "lighting",
         light(GL_LIGHT0, GL_AMBIENT),
         {[](Observations&) {
              GLint i[4];
              glGetLightiv(kBad, GL_AMBIENT, i);
          },
          [](Observations&) {
              GLint i[4];
              glGetLightiv(GL_LIGHT0, kBad, i);
          }}},
        {"glLightModelf",
         "lighting",
         API_CALL(glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1.0f)),
         {API_CALL(glLightModelf(kBad, 1.0f))},
         get({GL_LIGHT_MODEL_TWO_SIDE}),
         false,
         API_CALL(glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 0.0f))},
        {"glLightModeli",
         "lighting",
         API_CALL(glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1)),
         {API_CALL(glLightModeli(kBad, 1))},
         get({GL_LIGHT_MODEL_LOCAL_VIEWER}),
         false,
         API_CALL(glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 0))},
        {"glLightModelfv",
         "lighting",
         API_CALL(glLightModelfv(GL_LIGHT_MODEL_AMBIENT, kColor)),
         {API_CALL(glLightModelfv(kBad, kColor))},
         get({GL_LIGHT_MODEL_AMBIENT})},
        {"glLightModeliv",
         "lighting",
         API_CALL(glLightModeliv(GL_LIGHT_MODEL_AMBIENT, kColorI)),
         {API_CALL(glLightModeliv(kBad, kColorI))},
         get({GL_LIGHT_MODEL_AMBIENT})},
        {"glMaterialf",
         "lighting",
         API_CALL(glMaterialf(GL_FRONT, GL_SHININESS, 20.0f)),
         {API_CALL(glMaterialf(kBad, GL_SHININESS, 1.0f)), API_CALL(glMaterialf(GL_FRONT, kBad, 1.0f)),
          API_CALL(glMaterialf(GL_FRONT, GL_SHININESS, 129.0f))},
         material(GL_FRONT, GL_SHININESS),
         true},
        {"glMateriali",
         "lighting",
         API_CALL(glMateriali(GL_BACK, GL_SHININESS, 7)),
         {API_CALL(glMateriali(GL_BACK, GL_SHININESS, -1)), API_CALL(glMateriali(kBad, GL_SHININESS, 1)),
          API_CALL(glMateriali(GL_BACK, kBad, 1))},
         material(GL_BACK, GL_SHININESS),
         true},
        {"glMaterialfv",
         "lighting",
         API_CALL(glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, kColor)),
         {API_CALL(glMaterialfv(GL_FRONT_AND_BACK, kBad, kColor)), API_CALL(glMaterialfv(kBad, GL_DIFFUSE, kColor))},
         material(GL_BACK, GL_DIFFUSE),
         true},
        {"glMaterialiv",
         "lighting",
         API_CALL(glMaterialiv(GL_FRONT, GL_AMBIENT, kColorI)),
         {API_CALL(glMaterialiv(GL_FRONT, kBad, kColorI)), API_CALL(glMaterialiv(kBad, GL_AMBIENT, kColorI))},
         material(GL_FRONT, GL_AMBIENT),
         true},
        {"glGetMaterialfv",
         "lighting",
         material(GL_FRONT, GL_EMISSION),
         {[](Observations&) {
              GLfloat f[4];
              glGetMaterialfv(kBad, GL_AMBIENT, f);
          },
          [](Observations&) {
              GLfloat f[4];
              glGetMaterialfv(GL_FRONT, kBad, f);
          }}},
        {"glGetMaterialiv",
         "lighting",
         material(GL_BACK, GL_SPECULAR),
         {[](Observations&) {
              GLint i[4];
              glGetMaterialiv(GL_FRONT, kBad, i);
          },
          [](Observations&) {
              GLint i[4];
              glGetMaterialiv(kBad, GL_AMBIENT, i);
          }}},
        {"glColorMaterial",
         "lighting",
         API_CALL(glColorMaterial(GL_FRONT, GL_DIFFUSE)),
         {API_CALL(glColorMaterial(kBad, GL_DIFFUSE)), API_CALL(glColorMaterial(GL_FRONT, kBad)),
          API_CALL(glColorMaterial(GL_FRONT, GL_SHININESS))},
         get({GL_COLOR_MATERIAL_FACE, GL_COLOR_MATERIAL_PARAMETER})},

        // Fog.
        {"glFogf",
         "fog",
         API_CALL(glFogf(GL_FOG_DENSITY, 0.5f)),
         {API_CALL(glFogf(kBad, 1.0f)), API_CALL(glFogf(GL_FOG_DENSITY, -1.0f)), API_CALL(glFogf(GL_FOG_MODE, 1.0f))},
         get({GL_FOG_DENSITY, GL_FOG_MODE}),
         false,
         API_CALL(glFogf(GL_FOG_DENSITY, 1.0f))},
        {"glFogi",
         "fog",
         API_CALL(glFogi(GL_FOG_MODE, GL_LINEAR)),
         {API_CALL(glFogi(GL_FOG_MODE, GL_LINE)), API_CALL(glFogi(kBad, 1))},
         get({GL_FOG_MODE}),
         false,
         API_CALL(glFogi(GL_FOG_MODE, GL_EXP))},
        {"glFogfv",
         "fog",
         API_CALL(glFogfv(GL_FOG_COLOR, kColor)),
         {API_CALL(glFogfv(kBad, kColor))},
         get({GL_FOG_COLOR})},
        {"glFogiv",
         "fog",
         API_CALL(glFogiv(GL_FOG_COLOR, kColorI)),
         {API_CALL(glFogiv(kBad, kColorI)), API_CALL(const GLint mode = GL_LINE; glFogiv(GL_FOG_MODE, &mode))},
         get({GL_FOG_COLOR, GL_FOG_MODE})},

        // Per-fragment operations and buffers.
        {"glAlphaFunc",
         "fragment",
         API_CALL(glAlphaFunc(GL_GREATER, 0.25f)),
         {API_CALL(glAlphaFunc(kBad, 0.5f))},
         get({GL_ALPHA_TEST_FUNC, GL_ALPHA_TEST_REF})},
        {"glBlendFunc",
         "fragment",
         API_CALL(glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); glEnable(GL_BLEND)),
         {API_CALL(glBlendFunc(kBad, GL_ONE)), API_CALL(glBlendFunc(GL_ONE, kBad)),
          API_CALL(glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE))},
         drawn({GL_BLEND_SRC, GL_BLEND_DST}),
         false,
         API_CALL(glDisable(GL_BLEND); glBlendFunc(GL_ONE, GL_ZERO))},
        {"glLogicOp",
         "fragment",
         API_CALL(glLogicOp(GL_XOR); glEnable(GL_COLOR_LOGIC_OP)),
         {API_CALL(glLogicOp(kBad))},
         drawn({GL_LOGIC_OP_MODE}),
         false,
         API_CALL(glDisable(GL_COLOR_LOGIC_OP); glLogicOp(GL_COPY))},
        {"glStencilFunc",
         "fragment",
         API_CALL(glStencilFunc(GL_NOTEQUAL, 3, 0x0F)),
         {API_CALL(glStencilFunc(kBad, 0, 0xFF))},
         get({GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK}),
         false,
         API_CALL(glStencilFunc(GL_ALWAYS, 0, 0xFF))},
        {"glStencilOp",
         "fragment",
         API_CALL(glStencilOp(GL_INCR, GL_INVERT, GL_REPLACE)),
         {API_CALL(glStencilOp(kBad, GL_KEEP, GL_KEEP)), API_CALL(glStencilOp(GL_KEEP, kBad, GL_KEEP)),
          API_CALL(glStencilOp(GL_KEEP, GL_KEEP, kBad))},
         get({GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS}),
         false,
         API_CALL(glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP))},
        {"glStencilMask",
         "fragment",
         API_CALL(glStencilMask(0x3C)),
         {},
         get({GL_STENCIL_WRITEMASK}),
         false,
         API_CALL(glStencilMask(0xFF))},
        {"glClearStencil",
         "fragment",
         API_CALL(glClearStencil(5); glClear(GL_STENCIL_BUFFER_BIT)),
         {},
         [](Observations& o) {
             o.get({GL_STENCIL_CLEAR_VALUE});
             GLubyte s[4] = {0xA5, 0xA5, 0xA5, 0xA5};
             glReadPixels(3, 4, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
             o.bytes("stencil", s, 4);
         },
         false,
         API_CALL(glClearStencil(0))},
        {"glColorMask",
         "fragment",
         API_CALL(glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE)),
         {},
         drawn({GL_COLOR_WRITEMASK}),
         false,
         API_CALL(glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE))},
        {"glIndexMask", "fragment", API_CALL(glIndexMask(0x0F)), {}, get({GL_INDEX_WRITEMASK})},
        {"glDepthFunc",
         "fragment",
         API_CALL(glEnable(GL_DEPTH_TEST); glDepthFunc(GL_GREATER)),
         {API_CALL(glDepthFunc(kBad))},
         drawn({GL_DEPTH_FUNC})},
        {"glDepthMask",
         "fragment",
         API_CALL(glDepthMask(GL_FALSE)),
         {},
         drawn({GL_DEPTH_WRITEMASK}),
         false,
         API_CALL(glDepthMask(GL_TRUE))},
        {"glDepthRange",
         "fragment",
         API_CALL(glDepthRange(0.25, 0.75)),
         {},
         drawn({GL_DEPTH_RANGE}),
         false,
         API_CALL(glDepthRange(0.0, 1.0))},
        {"glScissor",
         "fragment",
         API_CALL(glScissor(5, 6, 30, 20); glEnable(GL_SCISSOR_TEST)),
         {API_CALL(glScissor(0, 0, -1, 5)), API_CALL(glScissor(0, 0, 5, -1))},
         drawn({GL_SCISSOR_BOX}),
         false,
         API_CALL(glDisable(GL_SCISSOR_TEST))},
        {"glClear",
         "buffers",
         API_CALL(glClearColor(0.2f, 0.3f, 0.4f, 0.5f); glClear(GL_COLOR_BUFFER_BIT)),
         {API_CALL(glClear(0x00000002)), API_CALL(glClear(GL_COLOR_BUFFER_BIT | 0x00800000))}},
        {"glClearColor", "buffers", API_CALL(glClearColor(0.1f, 1.5f, -0.5f, 0.75f)), {}, get({GL_COLOR_CLEAR_VALUE})},
        {"glClearDepth",
         "buffers",
         API_CALL(glClearDepth(0.375); glClear(GL_DEPTH_BUFFER_BIT)),
         {},
         get({GL_DEPTH_CLEAR_VALUE})},
        {"glClearIndex", "buffers", API_CALL(glClearIndex(7.5f)), {}, get({GL_INDEX_CLEAR_VALUE}), false, {}, false},
        // Compiled into a list, Mesa runs glClearIndex with the float's bits read as an integer
        // (7.5 gives 1089470464). An expected difference.
        {"glClearIndex:in_list", "buffers", API_CALL(glClearIndex(7.5f)), {}, get({GL_INDEX_CLEAR_VALUE})},
        {"glClearAccum",
         "buffers",
         API_CALL(glClearAccum(0.25f, -0.5f, 0.75f, 1.0f); glClear(GL_ACCUM_BUFFER_BIT)),
         {},
         get({GL_ACCUM_CLEAR_VALUE})},
        {"glAccum",
         "buffers",
         API_CALL(glClearColor(0.5f, 0.25f, 0.75f, 1.0f); glClear(GL_COLOR_BUFFER_BIT); glAccum(GL_LOAD, 0.5f);
                  glAccum(GL_ACCUM, 0.25f); glAccum(GL_MULT, 1.5f); glAccum(GL_RETURN, 1.0f)),
         {API_CALL(glAccum(kBad, 1.0f))}},
        {"glDrawBuffer",
         "buffers",
         API_CALL(glDrawBuffer(GL_FRONT_LEFT)),
         {API_CALL(glDrawBuffer(kBad)), API_CALL(glDrawBuffer(GL_BACK))},
         get({GL_DRAW_BUFFER}),
         false,
         API_CALL(glDrawBuffer(GL_FRONT))},
        {"glReadBuffer",
         "buffers",
         API_CALL(glReadBuffer(GL_FRONT_LEFT)),
         {API_CALL(glReadBuffer(kBad)), API_CALL(glReadBuffer(GL_BACK))},
         get({GL_READ_BUFFER}),
         false,
         API_CALL(glReadBuffer(GL_FRONT))},

        // The attribute stack (16 deep).
        {"glPushAttrib",
         "attrib",
         API_CALL(glPushAttrib(GL_ALL_ATTRIB_BITS); glLineWidth(3.0f)),
         {API_CALL(for (int i = 0; i < 17; ++i) glPushAttrib(GL_CURRENT_BIT))},
         get({GL_ATTRIB_STACK_DEPTH, GL_LINE_WIDTH}),
         false,
         API_CALL(popAllAttribs())},
        {"glPopAttrib",
         "attrib",
         API_CALL(glPushAttrib(GL_LINE_BIT | GL_ENABLE_BIT); glLineWidth(3.0f); glEnable(GL_FOG); glPopAttrib()),
         {API_CALL(glPopAttrib())},
         get({GL_ATTRIB_STACK_DEPTH, GL_LINE_WIDTH, GL_FOG}),
         false,
         API_CALL(popAllAttribs())},
    };
}

}  // namespace conformance
