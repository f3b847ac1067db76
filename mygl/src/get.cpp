// glGet* and glGetString: every query is answered once, as doubles, then converted to the
// caller's type the way the GL spec converts state values.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "capabilities.h"
#include "compiled.h"
#include "entry_points.h"
#include "fog_state.h"
#include "fragment_ops_state.h"
#include "polygon_offset_state.h"
#include "pixel_modes.h"
#include "textures.h"
#include <mygl/gl12_enums.h>

namespace mygl {
namespace {

struct Value {
    std::vector<double> numbers;
    bool isColorOrNormalized = false;  // integer queries map [-1, 1] to the full integer range
    bool isBoolean = false;
};

Value query(const Context::State& s, GLenum name) {
    auto one = [](double v) { return Value{{v}}; };
    auto flag = [](bool v) { return Value{{v ? 1.0 : 0.0}, false, true}; };
    auto matrix = [](const Matrix& m) {
        Value v;
        for (float f : m) v.numbers.push_back(f);
        return v;
    };
    const auto& d = *s.draw;
    switch (name) {
    case GL_VIEWPORT:
        return Value{{double(d.viewport.x), double(d.viewport.y), double(d.viewport.width), double(d.viewport.height)}};
    case GL_MODELVIEW_MATRIX: return matrix(s.modelview.top().matrix());
    case GL_PROJECTION_MATRIX: return matrix(s.projection.top().matrix());
    case GL_TEXTURE_MATRIX: return matrix(s.texture.top().matrix());
    case GL_MATRIX_MODE: return one(s.matrixMode);
    case GL_MODELVIEW_STACK_DEPTH: return one(double(s.modelview.depth()));
    case GL_PROJECTION_STACK_DEPTH: return one(double(s.projection.depth()));
    case GL_TEXTURE_STACK_DEPTH: return one(double(s.texture.depth()));
    case GL_MAX_MODELVIEW_STACK_DEPTH: return one(double(s.modelview.maxDepth()));
    case GL_MAX_PROJECTION_STACK_DEPTH: return one(double(s.projection.maxDepth()));
    case GL_MAX_TEXTURE_STACK_DEPTH: return one(double(s.texture.maxDepth()));
    case GL_ATTRIB_STACK_DEPTH: return one(double(s.attribStack.depth()));
    case GL_CLIENT_ATTRIB_STACK_DEPTH: return one(double(s.clientAttribStack.depth()));
    case GL_MAX_ATTRIB_STACK_DEPTH:
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: return one(double(AttribStack::kMaxDepth));
    case GL_MAX_VIEWPORT_DIMS: return Value{{double(Context::kMaxSize), double(Context::kMaxSize)}};
    case GL_CULL_FACE: return flag(d.cullEnabled);
    case GL_DEPTH_TEST: return flag(d.depthTest);
    case GL_CULL_FACE_MODE: return one(s.cullFaceMode);
    case GL_FRONT_FACE: return one(s.frontFace);
    case GL_DEPTH_FUNC: return one(s.depthFunc);
    case GL_DEPTH_WRITEMASK: return flag(d.depthWrite);
    case GL_SHADE_MODEL: return one(s.shadeModel);
    case GL_POLYGON_MODE: return Value{{double(s.polygonModeFront), double(s.polygonModeBack)}};
    case GL_LINE_WIDTH: return one(d.lineWidth);
    case GL_LINE_STIPPLE_PATTERN: return one(d.lineStipple.pattern);
    case GL_LINE_STIPPLE_REPEAT: return one(d.lineStipple.factor);
    // The reference's limits for points and lines, smooth or not.
    case GL_POINT_SIZE_RANGE:
    case GL_LINE_WIDTH_RANGE: return Value{{1.0, 255.0}};
    case GL_POINT_SIZE_GRANULARITY:
    case GL_LINE_WIDTH_GRANULARITY: return one(0.1f);
    case GL_POINT_SIZE: return one(d.pointSize);
    case GL_DEPTH_RANGE: return Value{{d.depthNear, d.depthFar}, true};
    case GL_COLOR_CLEAR_VALUE: return Value{{s.clearColor.r, s.clearColor.g, s.clearColor.b, s.clearColor.a}, true};
    case GL_DEPTH_CLEAR_VALUE: return Value{{s.clearDepth}, true};
    case GL_CURRENT_COLOR: return Value{{s.color.r, s.color.g, s.color.b, s.color.a}, true};
    case GL_CURRENT_NORMAL: return Value{{s.normal.x, s.normal.y, s.normal.z}, true};
    case GL_CURRENT_TEXTURE_COORDS: return Value{{s.texCoord.s, s.texCoord.t, s.texCoord.p, s.texCoord.q}};
    case GL_EDGE_FLAG: return flag(s.edgeFlag);
    case GL_CURRENT_RASTER_POSITION:
        return Value{{s.rasterPosition.x, s.rasterPosition.y, s.rasterPosition.z, s.rasterPosition.w}};
    case GL_CURRENT_RASTER_COLOR:
        return Value{{s.rasterColor.r, s.rasterColor.g, s.rasterColor.b, s.rasterColor.a}, true};
    case GL_CURRENT_RASTER_TEXTURE_COORDS:
        return Value{{s.rasterTexCoord.s, s.rasterTexCoord.t, s.rasterTexCoord.p, s.rasterTexCoord.q}};
    case GL_CURRENT_RASTER_DISTANCE: return one(s.rasterDistance);
    case GL_CURRENT_RASTER_INDEX: return one(1);  // an RGBA context's
    case GL_CURRENT_RASTER_POSITION_VALID: return flag(s.rasterValid);
    case GL_RED_BITS:
    case GL_GREEN_BITS:
    case GL_BLUE_BITS:
    case GL_ALPHA_BITS: return one(8);
    case GL_DEPTH_BITS: return one(24);
    case GL_STENCIL_BITS: return one(8);
    case GL_SUBPIXEL_BITS: return one(8);
    case GL_PACK_ALIGNMENT: return one(s.pack.alignment);
    case GL_UNPACK_ALIGNMENT: return one(s.unpack.alignment);
    case GL_PACK_ROW_LENGTH: return one(s.pack.rowLength);
    case GL_UNPACK_ROW_LENGTH: return one(s.unpack.rowLength);
    case GL_PACK_SKIP_PIXELS: return one(s.pack.skipPixels);
    case GL_UNPACK_SKIP_PIXELS: return one(s.unpack.skipPixels);
    case GL_PACK_SKIP_ROWS: return one(s.pack.skipRows);
    case GL_UNPACK_SKIP_ROWS: return one(s.unpack.skipRows);
    case GL_PACK_SWAP_BYTES: return flag(s.pack.swapBytes);
    case GL_UNPACK_SWAP_BYTES: return flag(s.unpack.swapBytes);
    case GL_PACK_LSB_FIRST: return flag(s.pack.lsbFirst);
    case GL_UNPACK_LSB_FIRST: return flag(s.unpack.lsbFirst);
    case GL_DOUBLEBUFFER: return flag(false);
    case GL_VERTEX_ARRAY: return flag(s.arrays.vertex.enabled);
    case GL_NORMAL_ARRAY: return flag(s.arrays.normal.enabled);
    case GL_COLOR_ARRAY: return flag(s.arrays.color.enabled);
    case GL_INDEX_ARRAY: return flag(s.arrays.index.enabled);
    case GL_TEXTURE_COORD_ARRAY: return flag(s.arrays.texCoord.enabled);
    case GL_EDGE_FLAG_ARRAY: return flag(s.arrays.edgeFlag.enabled);
    case GL_VERTEX_ARRAY_SIZE: return one(s.arrays.vertex.size);
    case GL_VERTEX_ARRAY_TYPE: return one(s.arrays.vertex.type);
    case GL_VERTEX_ARRAY_STRIDE: return one(s.arrays.vertex.stride);
    case GL_NORMAL_ARRAY_TYPE: return one(s.arrays.normal.type);
    case GL_NORMAL_ARRAY_STRIDE: return one(s.arrays.normal.stride);
    case GL_COLOR_ARRAY_SIZE: return one(s.arrays.color.size);
    case GL_COLOR_ARRAY_TYPE: return one(s.arrays.color.type);
    case GL_COLOR_ARRAY_STRIDE: return one(s.arrays.color.stride);
    case GL_INDEX_ARRAY_TYPE: return one(s.arrays.index.type);
    case GL_INDEX_ARRAY_STRIDE: return one(s.arrays.index.stride);
    case GL_TEXTURE_COORD_ARRAY_SIZE: return one(s.arrays.texCoord.size);
    case GL_TEXTURE_COORD_ARRAY_TYPE: return one(s.arrays.texCoord.type);
    case GL_TEXTURE_COORD_ARRAY_STRIDE: return one(s.arrays.texCoord.stride);
    case GL_EDGE_FLAG_ARRAY_STRIDE: return one(s.arrays.edgeFlag.stride);
    case GL_PERSPECTIVE_CORRECTION_HINT:
    case GL_POINT_SMOOTH_HINT:
    case GL_LINE_SMOOTH_HINT:
    case GL_POLYGON_SMOOTH_HINT:
    case GL_FOG_HINT: return one(s.hints.at(name));
    case GL_ACCUM_RED_BITS:
    case GL_ACCUM_GREEN_BITS:
    case GL_ACCUM_BLUE_BITS:
    case GL_ACCUM_ALPHA_BITS: return one(16);
    case GL_ACCUM_CLEAR_VALUE: {
        const auto& c = s.buffers.accumClear;
        return Value{{c[0], c[1], c[2], c[3]}, true};
    }
    case GL_DRAW_BUFFER: return one(s.buffers.drawBuffer);
    case GL_READ_BUFFER: return one(s.buffers.readBuffer);
    case GL_AUX_BUFFERS:
    case GL_INDEX_BITS: return one(0);
    case GL_STEREO:
    case GL_INDEX_MODE: return flag(false);
    case GL_RGBA_MODE: return flag(true);
    case GL_CURRENT_INDEX: return one(s.buffers.currentIndex);
    // Kept unsigned, answered as signed integers, as the reference does.
    case GL_INDEX_CLEAR_VALUE: return one(static_cast<GLint>(s.buffers.clearIndex));
    case GL_INDEX_WRITEMASK: return one(static_cast<GLint>(s.buffers.indexMask));
    case GL_LIST_BASE: return one(s.lists.base);
    case GL_RENDER_MODE: return one(s.renderMode);
    case GL_NAME_STACK_DEPTH: return one(double(s.selection.names.size()));
    case GL_MAX_NAME_STACK_DEPTH: return one(double(Selection::kMaxNameStackDepth));
    case GL_SELECTION_BUFFER_SIZE: return one(s.selection.size);
    case GL_FEEDBACK_BUFFER_SIZE: return one(s.feedback.size);
    case GL_FEEDBACK_BUFFER_TYPE: return one(s.feedback.type);
    case GL_LIST_INDEX: return one(s.lists.compilingName());
    case GL_LIST_MODE: return one(s.lists.compilingMode());
    case GL_MAX_LIST_NESTING: return one(DisplayLists::kMaxNesting);
    case GL_MAX_LIGHTS: return one(glrenderer::kMaxLights);
    case GL_MAX_CLIP_PLANES: return one(double(s.eyeClipPlanes.size()));
    case GL_MAX_EVAL_ORDER: return one(kMaxEvalOrder);
    case GL_MAP1_GRID_DOMAIN: return Value{{s.evaluators.grid1u1, s.evaluators.grid1u2}};
    case GL_MAP1_GRID_SEGMENTS: return one(s.evaluators.grid1un);
    case GL_MAP2_GRID_DOMAIN: {
        const Evaluators& e = s.evaluators;
        return Value{{e.grid2u1, e.grid2u2, e.grid2v1, e.grid2v2}};
    }
    case GL_MAP2_GRID_SEGMENTS: return Value{{double(s.evaluators.grid2un), double(s.evaluators.grid2vn)}};
    case GL_LIGHT_MODEL_AMBIENT: {
        const glm::vec4& a = s.lighting.modelAmbient;
        return Value{{a.r, a.g, a.b, a.a}, true};
    }
    case GL_LIGHT_MODEL_LOCAL_VIEWER: return flag(s.lighting.localViewer);
    case GL_LIGHT_MODEL_TWO_SIDE: return flag(s.lighting.twoSide);
    case GL_LIGHT_MODEL_COLOR_CONTROL:
        return one(s.lighting.separateSpecular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
    case GL_COLOR_MATERIAL_FACE: return one(s.colorMaterialFace);
    case GL_COLOR_MATERIAL_PARAMETER: return one(s.colorMaterialMode);
    default:
        if (const std::optional<bool> enabled = lightingCapability(s, name)) return flag(*enabled);
        if (const std::optional<bool> enabled = clipPlaneCapability(s, name)) return flag(*enabled);
        if (name == GL_FOG) return flag(s.fog.enabled);
        if (const std::optional<bool> offset = polygonOffsetCapability(s, name)) return flag(*offset);
        if (name == GL_POLYGON_OFFSET_FACTOR) return one(d.polygonOffset.factor);
        if (name == GL_POLYGON_OFFSET_UNITS) return one(d.polygonOffset.units);
        if (std::optional<std::vector<double>> fog = fogQuery(s, name)) return Value{*fog, name == GL_FOG_COLOR};
        if (const std::optional<bool> enabled = evaluatorCapability(s, name)) return flag(*enabled);
        if (name == GL_COLOR_WRITEMASK) return Value{*fragmentOpsQuery(s, name), false, true};
        if (std::optional<std::vector<double>> op = fragmentOpsQuery(s, name))
            return Value{*op, name == GL_ALPHA_TEST_REF};
        if (const std::optional<bool> enabled = textureCapability(s, name)) return flag(*enabled);
        if (const std::optional<bool> enabled = texGenCapability(s, name)) return flag(*enabled);
        if (std::optional<std::vector<double>> texture = textureQuery(s, name)) return Value{*texture};
        if (const std::optional<double> pixel = pixelModeValue(s.pixelModes, s.pixelMaps, name)) {
            return name == GL_MAP_COLOR || name == GL_MAP_STENCIL ? flag(*pixel != 0.0) : one(*pixel);
        }
        if (const std::optional<bool> enabled = capabilityEnabled(s, name)) return flag(*enabled);  // the inert ones
        return {};
    }
}

// Answers the query into `out` converted by `convert`, or records GL_INVALID_ENUM.
template <class T, class Convert>
void get(GLenum name, T* out, Convert convert) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    const Value value = query(*s, name);
    if (value.numbers.empty()) return setError(*s, GL_INVALID_ENUM);
    for (std::size_t i = 0; i < value.numbers.size(); ++i) out[i] = convert(value, value.numbers[i]);
}

GLint toInteger(const Value& v, double x) {
    if (std::isnan(x)) return 0;
    if (v.isColorOrNormalized) {  // [-1, 1] maps linearly onto the integer range, truncated as the reference does
        return static_cast<GLint>(std::clamp(x, -1.0, 1.0) * 2147483647.0);
    }
    return static_cast<GLint>(std::lround(std::clamp(x, -2147483648.0, 2147483647.0)));
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glGetDoublev,
           +[](GLenum name, GLdouble* out) { get(name, out, [](const Value&, double x) { return x; }); }>(),
    listed<gl::glGetFloatv,
           +[](GLenum name, GLfloat* out) {
               get(name, out, [](const Value&, double x) { return static_cast<GLfloat>(x); });
           }>(),
    listed<gl::glGetIntegerv, +[](GLenum name, GLint* out) { get(name, out, toInteger); }>(),
    listed<gl::glGetBooleanv,
           +[](GLenum name, GLboolean* out) {
               get(name, out, [](const Value&, double x) -> GLboolean { return x != 0.0 ? GL_TRUE : GL_FALSE; });
           }>(),
    listed<gl::glGetString,
           +[](GLenum name) -> const GLubyte* {
               Context::State* s = stateOutsideBeginEnd();
               if (!s) return nullptr;
               const char* text = name == GL_VENDOR       ? "MyGL"
                                  : name == GL_RENDERER   ? "MyGL software rasterizer"
                                  : name == GL_VERSION    ? "1.1 MyGL"
                                  : name == GL_EXTENSIONS ? ""
                                                          : nullptr;
               if (!text) setError(*s, GL_INVALID_ENUM);
               return reinterpret_cast<const GLubyte*>(text);
           }>(),
};

}  // namespace

std::span<const EntryPoint> getEntryPoints() { return kEntryPoints; }

}  // namespace mygl
