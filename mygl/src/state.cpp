// Enables and fixed-function state, translated into the pipeline's DrawState.
#include <algorithm>
#include <cmath>

#include "capabilities.h"
#include "clamp_to_unit.h"
#include "compiled.h"
#include "fog_state.h"
#include "fragment_ops_state.h"
#include "polygon_offset_state.h"
#include "stipple_state.h"
#include "textures.h"

namespace mygl {
namespace {

using glrenderer::CompareFunc;
using glrenderer::Face;
using glrenderer::PolygonMode;

// Capabilities a course program may toggle that have no effect on this pipeline (yet): accepted
// and remembered so that glIsEnabled answers, instead of failing with GL_INVALID_ENUM.
constexpr GLenum kInertCapabilities[] = {
    GL_DITHER,
    GL_POLYGON_SMOOTH,
};

bool isInert(GLenum cap) {
    return std::find(std::begin(kInertCapabilities), std::end(kInertCapabilities), cap) != std::end(kInertCapabilities);
}

void setCapability(GLenum cap, bool enabled) {
    Context::State* s = stateOutsideBeginEnd();
    if (s && !setCapability(*s, cap, enabled)) setError(*s, GL_INVALID_ENUM);
}

GLboolean isEnabled(GLenum cap) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return GL_FALSE;
    if (const ClientArray* array = s->arrays.find(cap)) return array->enabled;
    const std::optional<bool> enabled = capabilityEnabled(*s, cap);
    if (!enabled) setError(*s, GL_INVALID_ENUM);
    return enabled.value_or(false);
}

// Sets a state value after validation, ending the batch only when the value really changes.
template <class T, class U>
void assign(Context::State& s, T& field, U value) {
    if (field != static_cast<T>(value)) endBatch(s);
    field = static_cast<T>(value);
}

void cullFace(GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) return setError(*s, GL_INVALID_ENUM);
    s->cullFaceMode = mode;
    assign(*s, s->draw.edit().cullFace,
           mode == GL_FRONT  ? Face::Front
           : mode == GL_BACK ? Face::Back
                             : Face::FrontAndBack);
}

void frontFace(GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_CW && mode != GL_CCW) return setError(*s, GL_INVALID_ENUM);
    s->frontFace = mode;
    assign(*s, s->draw.edit().frontFaceCCW, mode == GL_CCW);
}

void depthFunc(GLenum func) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (func < GL_NEVER || func > GL_ALWAYS) return setError(*s, GL_INVALID_ENUM);
    s->depthFunc = func;
    assign(*s, s->draw.edit().depthFunc, static_cast<CompareFunc>(func - GL_NEVER));
}

void shadeModel(GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_FLAT && mode != GL_SMOOTH) return setError(*s, GL_INVALID_ENUM);
    s->shadeModel = mode;
    assign(*s, s->draw.edit().shadeModel,
           mode == GL_FLAT ? glrenderer::ShadeModel::Flat : glrenderer::ShadeModel::Smooth);
}

void polygonMode(GLenum face, GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) || mode < GL_POINT || mode > GL_FILL)
        return setError(*s, GL_INVALID_ENUM);
    const auto value = static_cast<PolygonMode>(mode - GL_POINT);
    if (face != GL_BACK) {
        s->polygonModeFront = mode;
        assign(*s, s->draw.edit().polygonFront, value);
    }
    if (face != GL_FRONT) {
        s->polygonModeBack = mode;
        assign(*s, s->draw.edit().polygonBack, value);
    }
}

// Only sizes <= 0 are errors: NaN is stored, as GL says and the reference does.
void positiveSize(float& field, GLfloat size) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (size <= 0.0f) return setError(*s, GL_INVALID_VALUE);
    assign(*s, field, size);
}

constexpr int kMaxViewportDimension = Context::kMaxSize;

void viewport(GLint x, GLint y, GLsizei width, GLsizei height) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    // Sizes clamp to GL_MAX_VIEWPORT_DIMS; the origin to the bounds the reference keeps it in.
    const int bound = 2 * kMaxViewportDimension;
    const glrenderer::Viewport v{std::clamp(x, -bound, bound - 1), std::clamp(y, -bound, bound - 1),
                                 std::min(width, kMaxViewportDimension), std::min(height, kMaxViewportDimension)};
    assign(*s, s->draw.edit().viewport, v);
}

void depthRange(GLdouble nearVal, GLdouble farVal) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    assign(*s, s->draw.edit().depthNear, static_cast<float>(clampToUnit(nearVal)));
    assign(*s, s->draw.edit().depthFar, static_cast<float>(clampToUnit(farVal)));
}

void pixelStore(GLenum name, GLint value) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const bool pack = name >= GL_PACK_SWAP_BYTES && name <= GL_PACK_ALIGNMENT;
    if (!pack && !(name >= GL_UNPACK_SWAP_BYTES && name <= GL_UNPACK_ALIGNMENT)) return setError(*s, GL_INVALID_ENUM);
    PixelStoreModes& modes = pack ? s->pack : s->unpack;
    const GLenum unpackName = pack ? name - GL_PACK_SWAP_BYTES + GL_UNPACK_SWAP_BYTES : name;
    switch (unpackName) {
    case GL_UNPACK_SWAP_BYTES: modes.swapBytes = value != 0; return;
    case GL_UNPACK_LSB_FIRST: modes.lsbFirst = value != 0; return;
    case GL_UNPACK_ALIGNMENT:
        if (value != 1 && value != 2 && value != 4 && value != 8) return setError(*s, GL_INVALID_VALUE);
        modes.alignment = value;
        return;
    default:
        if (value < 0) return setError(*s, GL_INVALID_VALUE);
        (unpackName == GL_UNPACK_ROW_LENGTH  ? modes.rowLength
         : unpackName == GL_UNPACK_SKIP_ROWS ? modes.skipRows
                                             : modes.skipPixels) = value;
    }
}

// Hints change nothing here (the reference renders the same either way) but are checked and
// kept for glGet.
void hint(GLenum target, GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) return setError(*s, GL_INVALID_ENUM);
    const auto found = s->hints.find(target);
    if (found == s->hints.end()) return setError(*s, GL_INVALID_ENUM);
    found->second = mode;
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glEnable, +[](GLenum cap) { setCapability(cap, true); }>(),
    listed<gl::glDisable, +[](GLenum cap) { setCapability(cap, false); }>(),
    listed<gl::glIsEnabled, +[](GLenum cap) { return isEnabled(cap); }>(),
    listed<gl::glCullFace, +[](GLenum mode) { cullFace(mode); }>(),
    listed<gl::glFrontFace, +[](GLenum mode) { frontFace(mode); }>(),
    listed<gl::glDepthFunc, +[](GLenum func) { depthFunc(func); }>(),
    listed<gl::glDepthMask,
           +[](GLboolean flag) {
               if (Context::State* s = stateOutsideBeginEnd()) assign(*s, s->draw.edit().depthWrite, flag != GL_FALSE);
           }>(),
    listed<gl::glShadeModel, +[](GLenum mode) { shadeModel(mode); }>(),
    listed<gl::glPolygonMode, +[](GLenum face, GLenum mode) { polygonMode(face, mode); }>(),
    listed<gl::glLineWidth,
           +[](GLfloat width) {
               if (Context::State* s = currentState()) positiveSize(s->draw.edit().lineWidth, width);
           }>(),
    listed<gl::glPointSize,
           +[](GLfloat size) {
               if (Context::State* s = currentState()) positiveSize(s->draw.edit().pointSize, size);
           }>(),
    listed<gl::glViewport, +[](GLint x, GLint y, GLsizei w, GLsizei h) { viewport(x, y, w, h); }>(),
    listed<gl::glDepthRange, +[](GLdouble n, GLdouble f) { depthRange(n, f); }>(),
    listed<gl::glClearColor,
           +[](GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
               if (Context::State* s = stateOutsideBeginEnd())
                   s->clearColor = {clampToUnit(r), clampToUnit(g), clampToUnit(b), clampToUnit(a)};
           }>(),
    listed<gl::glClearDepth,
           +[](GLdouble depth) {
               if (Context::State* s = stateOutsideBeginEnd()) s->clearDepth = clampToUnit(depth);
           }>(),
    listed<gl::glPixelStorei, +[](GLenum name, GLint value) { pixelStore(name, value); }>(),
    listed<gl::glPixelStoref,
           +[](GLenum name, GLfloat value) {
               // Booleans are any non-zero value; counts round to the nearest integer.
               const bool flag = name == GL_PACK_SWAP_BYTES || name == GL_PACK_LSB_FIRST ||
                                 name == GL_UNPACK_SWAP_BYTES || name == GL_UNPACK_LSB_FIRST;
               pixelStore(name, flag ? GLint{value != 0.0f} : static_cast<GLint>(std::lround(value)));
           }>(),
    listed<gl::glHint, +[](GLenum target, GLenum mode) { hint(target, mode); }>(),
    listed<gl::glGetError,
           +[]() -> GLenum {
               Context::State* s = stateOutsideBeginEnd();
               if (!s) return GL_NO_ERROR;  // no context, or inside glBegin/glEnd (that error is now pending)
               const GLenum error = s->error;
               s->error = GL_NO_ERROR;
               return error;
           }>(),
};

}  // namespace

bool setCapability(Context::State& s, GLenum cap, bool enabled) {
    if (cap == GL_CULL_FACE || cap == GL_DEPTH_TEST || cap == GL_POINT_SMOOTH || cap == GL_LINE_SMOOTH) {
        bool& flag = cap == GL_CULL_FACE      ? s.draw.edit().cullEnabled
                     : cap == GL_DEPTH_TEST   ? s.draw.edit().depthTest
                     : cap == GL_POINT_SMOOTH ? s.draw.edit().pointSmooth
                                              : s.draw.edit().lineSmooth;
        if (flag != enabled) endBatch(s);
        flag = enabled;
        return true;
    }
    if (setLightingCapability(s, cap, enabled) || setClipPlaneCapability(s, cap, enabled) ||
        setEvaluatorCapability(s, cap, enabled) || setPolygonOffsetCapability(s, cap, enabled) ||
        setFragmentOpsCapability(s, cap, enabled) || setStippleCapability(s, cap, enabled)) {
        return true;
    }
    if (setTextureCapability(s, cap, enabled) || setTexGenCapability(s, cap, enabled)) return true;
    if (cap == GL_FOG) {
        s.fog.enabled = enabled;
        updateFog(s);
        return true;
    }
    if (!isInert(cap)) return false;
    auto& list = s.otherEnabled;
    const auto found = std::find(list.begin(), list.end(), cap);
    if (enabled && found == list.end()) list.push_back(cap);
    if (!enabled && found != list.end()) list.erase(found);
    return true;
}

std::optional<bool> capabilityEnabled(const Context::State& s, GLenum cap) {
    if (cap == GL_CULL_FACE) return s.draw->cullEnabled;
    if (cap == GL_DEPTH_TEST) return s.draw->depthTest;
    if (cap == GL_POINT_SMOOTH) return s.draw->pointSmooth;
    if (cap == GL_LINE_SMOOTH) return s.draw->lineSmooth;
    if (const std::optional<bool> lighting = lightingCapability(s, cap)) return *lighting;
    if (const std::optional<bool> plane = clipPlaneCapability(s, cap)) return *plane;
    if (cap == GL_FOG) return s.fog.enabled;
    if (const std::optional<bool> texture = textureCapability(s, cap)) return *texture;
    if (const std::optional<bool> gen = texGenCapability(s, cap)) return *gen;
    if (const std::optional<bool> offset = polygonOffsetCapability(s, cap)) return *offset;
    if (const std::optional<bool> map = evaluatorCapability(s, cap)) return *map;
    if (const std::optional<bool> op = fragmentOpsCapability(s, cap)) return *op;
    if (const std::optional<bool> stipple = stippleCapability(s, cap)) return *stipple;
    if (!isInert(cap)) return std::nullopt;
    return std::find(s.otherEnabled.begin(), s.otherEnabled.end(), cap) != s.otherEnabled.end();
}

std::span<const EntryPoint> stateEntryPoints() { return kEntryPoints; }

}  // namespace mygl
