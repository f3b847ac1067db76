// glGet completeness: every GL 1.1 state value of the spec's state tables (and the
// implementation-dependent values) queried on MyGL and on OSMesa, as doubles, integers and
// booleans, after a walk that moves much of the state off its initial value.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

const GLenum kStateValues[] = {
    // Current values
    GL_CURRENT_COLOR,
    GL_CURRENT_INDEX,
    GL_CURRENT_TEXTURE_COORDS,
    GL_CURRENT_NORMAL,
    GL_CURRENT_RASTER_POSITION,
    GL_CURRENT_RASTER_DISTANCE,
    GL_CURRENT_RASTER_COLOR,
    GL_CURRENT_RASTER_INDEX,
    GL_CURRENT_RASTER_TEXTURE_COORDS,
    GL_CURRENT_RASTER_POSITION_VALID,
    GL_EDGE_FLAG,
    // Vertex arrays
    GL_VERTEX_ARRAY,
    GL_VERTEX_ARRAY_SIZE,
    GL_VERTEX_ARRAY_TYPE,
    GL_VERTEX_ARRAY_STRIDE,
    GL_NORMAL_ARRAY,
    GL_NORMAL_ARRAY_TYPE,
    GL_NORMAL_ARRAY_STRIDE,
    GL_COLOR_ARRAY,
    GL_COLOR_ARRAY_SIZE,
    GL_COLOR_ARRAY_TYPE,
    GL_COLOR_ARRAY_STRIDE,
    GL_INDEX_ARRAY,
    GL_INDEX_ARRAY_TYPE,
    GL_INDEX_ARRAY_STRIDE,
    GL_TEXTURE_COORD_ARRAY,
    GL_TEXTURE_COORD_ARRAY_SIZE,
    GL_TEXTURE_COORD_ARRAY_TYPE,
    GL_TEXTURE_COORD_ARRAY_STRIDE,
    GL_EDGE_FLAG_ARRAY,
    GL_EDGE_FLAG_ARRAY_STRIDE,
    // Transformation
    GL_MODELVIEW_MATRIX,
    GL_PROJECTION_MATRIX,
    GL_TEXTURE_MATRIX,
    GL_VIEWPORT,
    GL_DEPTH_RANGE,
    GL_MODELVIEW_STACK_DEPTH,
    GL_PROJECTION_STACK_DEPTH,
    GL_TEXTURE_STACK_DEPTH,
    GL_MATRIX_MODE,
    GL_NORMALIZE,
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
    // Colouring and lighting
    GL_FOG_COLOR,
    GL_FOG_INDEX,
    GL_FOG_DENSITY,
    GL_FOG_START,
    GL_FOG_END,
    GL_FOG_MODE,
    GL_FOG,
    GL_SHADE_MODEL,
    GL_LIGHTING,
    GL_COLOR_MATERIAL,
    GL_COLOR_MATERIAL_PARAMETER,
    GL_COLOR_MATERIAL_FACE,
    GL_LIGHT_MODEL_AMBIENT,
    GL_LIGHT_MODEL_LOCAL_VIEWER,
    GL_LIGHT_MODEL_TWO_SIDE,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    // Rasterization
    GL_POINT_SIZE,
    GL_POINT_SMOOTH,
    GL_LINE_WIDTH,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_LINE_STIPPLE_PATTERN,
    GL_LINE_STIPPLE_REPEAT,
    GL_CULL_FACE,
    GL_CULL_FACE_MODE,
    GL_FRONT_FACE,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_MODE,
    GL_POLYGON_OFFSET_FACTOR,
    GL_POLYGON_OFFSET_UNITS,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_STIPPLE,
    // Texturing
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_BINDING_1D,
    GL_TEXTURE_BINDING_2D,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
    GL_MAX_TEXTURE_SIZE,
    // Pixel operations
    GL_SCISSOR_TEST,
    GL_ALPHA_TEST,
    GL_STENCIL_TEST,
    GL_DEPTH_TEST,
    GL_DEPTH_FUNC,
    GL_BLEND,
    GL_DITHER,
    GL_SCISSOR_BOX,
    GL_ALPHA_TEST_FUNC,
    GL_ALPHA_TEST_REF,
    GL_STENCIL_FUNC,
    GL_STENCIL_VALUE_MASK,
    GL_STENCIL_REF,
    GL_STENCIL_FAIL,
    GL_STENCIL_PASS_DEPTH_FAIL,
    GL_STENCIL_PASS_DEPTH_PASS,
    GL_STENCIL_WRITEMASK,
    GL_STENCIL_CLEAR_VALUE,
    GL_STENCIL_BITS,
    GL_BLEND_SRC,
    GL_BLEND_DST,
    GL_LOGIC_OP_MODE,
    GL_INDEX_LOGIC_OP,
    GL_COLOR_LOGIC_OP,
    GL_COLOR_WRITEMASK,
    // Framebuffer control
    GL_DRAW_BUFFER,
    GL_INDEX_WRITEMASK,
    GL_DEPTH_WRITEMASK,
    GL_COLOR_CLEAR_VALUE,
    GL_INDEX_CLEAR_VALUE,
    GL_DEPTH_CLEAR_VALUE,
    GL_ACCUM_CLEAR_VALUE,
    // Pixels
    GL_UNPACK_ALIGNMENT,
    GL_PACK_ALIGNMENT,
    GL_READ_BUFFER,
    GL_PACK_SWAP_BYTES,
    GL_PACK_LSB_FIRST,
    GL_PACK_ROW_LENGTH,
    GL_PACK_SKIP_ROWS,
    GL_PACK_SKIP_PIXELS,
    GL_UNPACK_SWAP_BYTES,
    GL_UNPACK_LSB_FIRST,
    GL_UNPACK_ROW_LENGTH,
    GL_UNPACK_SKIP_ROWS,
    GL_UNPACK_SKIP_PIXELS,
    // Evaluators
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP1_INDEX,
    GL_MAP1_COLOR_4,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_MAP2_INDEX,
    GL_MAP2_COLOR_4,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
    GL_MAP1_GRID_DOMAIN,
    GL_MAP2_GRID_DOMAIN,
    GL_MAP1_GRID_SEGMENTS,
    GL_MAP2_GRID_SEGMENTS,
    GL_AUTO_NORMAL,
    // Hints
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
    // Implementation-dependent values
    GL_MAX_LIGHTS,
    GL_MAX_CLIP_PLANES,
    GL_MAX_MODELVIEW_STACK_DEPTH,
    GL_MAX_PROJECTION_STACK_DEPTH,
    GL_MAX_TEXTURE_STACK_DEPTH,
    GL_SUBPIXEL_BITS,
    GL_MAX_NAME_STACK_DEPTH,
    GL_MAX_LIST_NESTING,
    GL_MAX_EVAL_ORDER,
    GL_MAX_VIEWPORT_DIMS,
    GL_MAX_ATTRIB_STACK_DEPTH,
    GL_MAX_CLIENT_ATTRIB_STACK_DEPTH,
    GL_AUX_BUFFERS,
    GL_RGBA_MODE,
    GL_INDEX_MODE,
    GL_DOUBLEBUFFER,
    GL_STEREO,
    GL_POINT_SIZE_RANGE,
    GL_POINT_SIZE_GRANULARITY,
    GL_LINE_WIDTH_RANGE,
    GL_LINE_WIDTH_GRANULARITY,
    GL_RED_BITS,
    GL_GREEN_BITS,
    GL_BLUE_BITS,
    GL_ALPHA_BITS,
    GL_INDEX_BITS,
    GL_DEPTH_BITS,
    GL_ACCUM_RED_BITS,
    GL_ACCUM_GREEN_BITS,
    GL_ACCUM_BLUE_BITS,
    GL_ACCUM_ALPHA_BITS,
    // Miscellaneous
    GL_LIST_BASE,
    GL_LIST_INDEX,
    GL_LIST_MODE,
    GL_ATTRIB_STACK_DEPTH,
    GL_CLIENT_ATTRIB_STACK_DEPTH,
    GL_NAME_STACK_DEPTH,
    GL_RENDER_MODE,
    GL_SELECTION_BUFFER_SIZE,
    GL_FEEDBACK_BUFFER_SIZE,
    GL_FEEDBACK_BUFFER_TYPE,
    // Pixel modes
    GL_MAP_COLOR,
    GL_MAP_STENCIL,
    GL_INDEX_SHIFT,
    GL_INDEX_OFFSET,
    GL_RED_SCALE,
    GL_RED_BIAS,
    GL_GREEN_SCALE,
    GL_GREEN_BIAS,
    GL_BLUE_SCALE,
    GL_BLUE_BIAS,
    GL_ALPHA_SCALE,
    GL_ALPHA_BIAS,
    GL_DEPTH_SCALE,
    GL_DEPTH_BIAS,
    GL_ZOOM_X,
    GL_ZOOM_Y,
    GL_PIXEL_MAP_I_TO_I_SIZE,
    GL_PIXEL_MAP_S_TO_S_SIZE,
    GL_PIXEL_MAP_I_TO_R_SIZE,
    GL_PIXEL_MAP_I_TO_G_SIZE,
    GL_PIXEL_MAP_I_TO_B_SIZE,
    GL_PIXEL_MAP_I_TO_A_SIZE,
    GL_PIXEL_MAP_R_TO_R_SIZE,
    GL_PIXEL_MAP_G_TO_G_SIZE,
    GL_PIXEL_MAP_B_TO_B_SIZE,
    GL_PIXEL_MAP_A_TO_A_SIZE,
    GL_MAX_PIXEL_MAP_TABLE,
};

// Moves state off its initial values (each area's own tests go further).
void changeState() {
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glNormal3f(0.0f, 0.6f, 0.8f);
    glTexCoord2f(0.5f, 0.25f);
    glIndexf(3.0f);
    glEdgeFlag(GL_FALSE);
    glRasterPos3f(0.25f, -0.5f, 0.1f);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -0.75, 0.75, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.1f, 0.2f, -3.0f);
    glPushMatrix();
    glViewport(2, 3, 10, 9);
    glDepthRange(0.2, 0.9);
    glEnable(GL_NORMALIZE);
    glEnable(GL_CLIP_PLANE2);
    glFogf(GL_FOG_DENSITY, 0.4f);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glShadeModel(GL_FLAT);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_BACK, GL_SPECULAR);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_LIGHT3);
    glPointSize(2.5f);
    glLineWidth(3.0f);
    glLineStipple(3, 0xC3A5);
    glEnable(GL_LINE_STIPPLE);
    static const GLubyte kStipple[128] = {0x12, 0x34, 0x56, 0x78, 0x9A, 0xBC, 0xDE, 0xF0, 0x0F, 0xF0};
    glPolygonStipple(kStipple);
    glEnable(GL_POLYGON_STIPPLE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CW);
    glPolygonMode(GL_BACK, GL_LINE);
    glPolygonOffset(1.5f, 2.0f);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_DITHER);
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_FRONT_AND_BACK);
    glIndexMask(0x0F);
    glPixelZoom(-1.5f, 0.5f);
    glPixelTransferf(GL_GREEN_SCALE, 0.75f);
    glPixelTransferi(GL_INDEX_SHIFT, 2);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    const GLfloat map[4] = {0.25f, 0.5f, 1.0f, 0.0f};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, map);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearIndex(7.0f);
    glClearDepth(0.75);
    glClearAccum(-0.5f, 0.25f, 0.0f, 1.0f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(4, 0.0f, 1.0f, 6, -1.0f, 2.0f);
    glHint(GL_FOG_HINT, GL_NICEST);
    glHint(GL_LINE_SMOOTH_HINT, GL_FASTEST);
    glListBase(5);
    glPushAttrib(GL_LIGHTING_BIT);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    static GLfloat vertices[8];
    glVertexPointer(2, GL_FLOAT, 8, vertices);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, vertices);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
}

// The matrices as integers: a departure of the reference, which converts them as normalized
// values (1.0 gives INT_MAX) where the spec rounds them; MyGL rounds (docs/reference-rules.md).
bool integerAnswerDeparts(GLenum name) {
    return name == GL_MODELVIEW_MATRIX || name == GL_PROJECTION_MATRIX || name == GL_TEXTURE_MATRIX;
}

// Every value as doubles, integers and booleans, with the error each query left.
std::vector<double> queryAll() {
    std::vector<double> out;
    for (GLenum name : kStateValues) {
        GLdouble d[16];
        GLint i[16];
        GLboolean b[16];
        std::fill(std::begin(d), std::end(d), -12345.0);
        std::fill(std::begin(i), std::end(i), -12345);
        std::fill(std::begin(b), std::end(b), GLboolean(7));
        glGetDoublev(name, d);
        if (!integerAnswerDeparts(name)) glGetIntegerv(name, i);
        glGetBooleanv(name, b);
        out.push_back(name);
        for (int k = 0; k < 16; ++k) out.insert(out.end(), {d[k], double(i[k]), double(b[k])});
        out.push_back(glGetError());
    }
    // The polygon stipple, which only glGetPolygonStipple returns (rows 8 bytes apart under
    // changeState's pack alignment).
    GLubyte stipple[256] = {};
    glGetPolygonStipple(stipple);
    out.insert(out.end(), std::begin(stipple), std::end(stipple));
    out.push_back(glGetError());
    return out;
}

// The name of the state value whose answers first differ.
std::string firstDifferingName(const std::vector<double>& ours, const std::vector<double>& theirs) {
    const std::string where = testing_support::firstDifference(ours, theirs);
    if (where.empty()) return "";
    const std::size_t index = std::stoul(where);
    const std::size_t perName = 2 + 16 * 3;
    return "GL enum 0x" +
           [&] {
               char hex[16];
               std::snprintf(hex, sizeof hex, "%X", static_cast<unsigned>(ours[index / perName * perName]));
               return std::string(hex);
           }() +
           " at " + where;
}

TEST(GetCompleteness, InitialValuesMatchTheReference) {
    const auto values = onBothBackends<std::vector<double>>(queryAll);
    EXPECT_EQ(firstDifferingName(values.mygl, values.osmesa), "");
}

TEST(GetCompleteness, ChangedValuesMatchTheReference) {
    const auto values = onBothBackends<std::vector<double>>([] {
        changeState();
        return queryAll();
    });
    EXPECT_EQ(firstDifferingName(values.mygl, values.osmesa), "");
}

}  // namespace

namespace {

// glHint for every GL 1.1 target and mode, bad targets and modes, inside glBegin/glEnd and in a
// display list: the value of each target and the error after each call.
std::vector<double> hintWalk() {
    const GLenum targets[] = {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
                              GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT};
    std::vector<double> out;
    const auto all = [&] {
        for (GLenum t : targets) {
            GLint v = -1;
            glGetIntegerv(t, &v);
            out.push_back(v);
        }
        out.push_back(glGetError());
    };
    all();
    for (GLenum t : targets) {
        for (GLenum mode : {GL_FASTEST, GL_NICEST, GL_DONT_CARE, GL_NICEST}) {
            glHint(t, mode);
            all();
        }
        glHint(t, GL_FOG);
        all();
    }
    glHint(GL_FOG, GL_NICEST);
    all();
    glHint(GL_LINE_SMOOTH, GL_NICEST);
    all();
    glBegin(GL_POINTS);
    glHint(GL_FOG_HINT, GL_FASTEST);
    glEnd();
    all();
    glNewList(1, GL_COMPILE);
    glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
    glHint(GL_POINT_SMOOTH_HINT, 0);
    glEndList();
    all();
    glCallList(1);
    all();
    return out;
}

TEST(Hints, EveryTargetModeAndErrorMatchesTheReference) {
    const auto walks = onBothBackends<std::vector<double>>(hintWalk);
    EXPECT_EQ(testing_support::firstDifference(walks.mygl, walks.osmesa), "");
}

}  // namespace
