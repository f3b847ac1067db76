// glLight, glMaterial, glLightModel, glColorMaterial and their queries, translated into the
// pipeline's LightingState; and the lit colour of a vertex.
#include <array>
#include <cmath>

#include "clamp_to_unit.h"
#include "compiled.h"
#include <mygl/gl12_enums.h>
#include "vertex_input.h"

namespace mygl {
namespace {

using glrenderer::LightSource;
using glrenderer::Material;

// The spec's integer-to-float conversion of colours given as integers (INT_TO_FLOAT).
float intColor(GLint v) { return toFloat(v); }

// The light a GL_LIGHTi names, or nullptr and GL_INVALID_ENUM.
LightSource* lightOf(Context::State& s, GLenum light) {
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + glrenderer::kMaxLights) {
        setError(s, GL_INVALID_ENUM);
        return nullptr;
    }
    return &s.lighting.lights[light - GL_LIGHT0];
}

// The eye-space value of a position or direction given now (Mesa's TRANSFORM_POINT and
// TRANSFORM_DIRECTION with the modelview's upper rows).
glm::vec4 toEye(const Context::State& s, const glm::vec4& v, bool point) {
    const Matrix& m = s.modelview.top().matrix();
    glm::vec4 r{0.0f, 0.0f, 0.0f, v.w};
    for (int row = 0; row < (point ? 4 : 3); ++row) {
        r[row] = at(m, row, 0) * v.x + at(m, row, 1) * v.y + at(m, row, 2) * v.z;
        if (point) r[row] = r[row] + at(m, row, 3) * v.w;
    }
    return r;
}

void light(GLenum lightName, GLenum name, const GLfloat* p) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !p) return;
    LightSource* l = lightOf(*s, lightName);
    if (!l) return;
    switch (name) {
    case GL_AMBIENT: l->ambient = {p[0], p[1], p[2], p[3]}; break;
    case GL_DIFFUSE: l->diffuse = {p[0], p[1], p[2], p[3]}; break;
    case GL_SPECULAR: l->specular = {p[0], p[1], p[2], p[3]}; break;
    case GL_POSITION: l->position = toEye(*s, {p[0], p[1], p[2], p[3]}, true); break;
    case GL_SPOT_DIRECTION: {
        const glm::vec4 d = toEye(*s, {p[0], p[1], p[2], 0.0f}, false);
        l->spotDirection = {d.x, d.y, d.z};
        break;
    }
    case GL_SPOT_EXPONENT:
        if (p[0] < 0.0f || p[0] > 128.0f) return setError(*s, GL_INVALID_VALUE);
        l->spotExponent = p[0];
        break;
    case GL_SPOT_CUTOFF:
        if ((p[0] < 0.0f || p[0] > 90.0f) && p[0] != 180.0f) return setError(*s, GL_INVALID_VALUE);
        l->spotCutoff = p[0];
        break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
        if (p[0] < 0.0f) return setError(*s, GL_INVALID_VALUE);
        (name == GL_CONSTANT_ATTENUATION ? l->constantAttenuation
         : name == GL_LINEAR_ATTENUATION ? l->linearAttenuation
                                         : l->quadraticAttenuation) = p[0];
        break;
    default: return setError(*s, GL_INVALID_ENUM);
    }
    endBatch(*s);
}

template <class T>
void lightv(GLenum lightName, GLenum name, const T* p) {
    if (!p) return;
    std::array<GLfloat, 4> f{};
    const bool color = name == GL_AMBIENT || name == GL_DIFFUSE || name == GL_SPECULAR;
    for (std::size_t i = 0; i < glcalls::lightCount(lightName, name, p); ++i) {
        f[i] = color && std::is_same_v<T, GLint> ? intColor(static_cast<GLint>(p[i])) : static_cast<GLfloat>(p[i]);
    }
    light(lightName, name, f.data());
}

// The material colours glColorMaterial makes follow the current colour, per face.
glrenderer::ColorMaterial followed(GLenum mode) {
    return {mode == GL_EMISSION, mode == GL_AMBIENT || mode == GL_AMBIENT_AND_DIFFUSE,
            mode == GL_DIFFUSE || mode == GL_AMBIENT_AND_DIFFUSE, mode == GL_SPECULAR};
}

// Copies the current colour into the materials that follow it, as the reference does at each
// glColor while GL_COLOR_MATERIAL is enabled (glGetMaterial then reports it).
void storeFollowedColors(Context::State& s) {
    for (std::size_t face = 0; face < 2; ++face) {
        const glrenderer::ColorMaterial& f = s.lighting.colorMaterial[face];
        Material& m = s.lighting.materials[face];
        if (f.emission) m.emission = s.color;
        if (f.ambient) m.ambient = s.color;
        if (f.diffuse) m.diffuse = s.color;
        if (f.specular) m.specular = s.color;
    }
}

void updateColorMaterial(Context::State& s) {
    storeFollowedColors(s);
    const glrenderer::ColorMaterial none, tracked = followed(s.colorMaterialMode);
    const bool on = s.colorMaterialEnabled;
    s.lighting.colorMaterial[0] = on && s.colorMaterialFace != GL_BACK ? tracked : none;
    s.lighting.colorMaterial[1] = on && s.colorMaterialFace != GL_FRONT ? tracked : none;
    storeFollowedColors(s);
}

// glMaterial, also allowed between glBegin and glEnd (the vertices after it take the new
// material).
void material(GLenum face, GLenum name, const GLfloat* p) {
    Context::State* s = currentState();
    if (!s || !p) return;
    if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return setError(*s, GL_INVALID_ENUM);
    const glm::vec4 v{p[0], p[1], p[2], p[3]};
    if (name == GL_SHININESS && (p[0] < 0.0f || p[0] > 128.0f)) return setError(*s, GL_INVALID_VALUE);
    if (name != GL_AMBIENT && name != GL_DIFFUSE && name != GL_SPECULAR && name != GL_EMISSION &&
        name != GL_SHININESS && name != GL_AMBIENT_AND_DIFFUSE && name != GL_COLOR_INDEXES) {
        return setError(*s, GL_INVALID_ENUM);
    }
    if (!s->insideBeginEnd) endBatch(*s);
    if (s->insideBeginEnd && s->lightingEnabled && !s->lightingOnProgramThread) {
        s->pipeline.lightOpenBatch();  // the vertices so far keep the material they had
        s->lightingOnProgramThread = true;
    }
    s->lightingStale = true;
    for (std::size_t i = 0; i < 2; ++i) {
        if ((i == 0 && face == GL_BACK) || (i == 1 && face == GL_FRONT)) continue;
        Material& m = s->lighting.materials[i];
        const glrenderer::ColorMaterial& f = s->lighting.colorMaterial[i];  // those follow the colour instead
        if (name == GL_EMISSION && !f.emission) m.emission = v;
        if ((name == GL_AMBIENT || name == GL_AMBIENT_AND_DIFFUSE) && !f.ambient) m.ambient = v;
        if ((name == GL_DIFFUSE || name == GL_AMBIENT_AND_DIFFUSE) && !f.diffuse) m.diffuse = v;
        if (name == GL_SPECULAR && !f.specular) m.specular = v;
        if (name == GL_SHININESS) m.shininess = p[0];
    }
}

template <class T>
void materialv(GLenum face, GLenum name, const T* p) {
    if (!p) return;
    std::array<GLfloat, 4> f{};
    for (std::size_t i = 0; i < glcalls::materialCount(face, name, p); ++i) {
        f[i] = std::is_same_v<T, GLint> && name != GL_SHININESS && name != GL_COLOR_INDEXES
                   ? intColor(static_cast<GLint>(p[i]))
                   : static_cast<GLfloat>(p[i]);
    }
    material(face, name, f.data());
}

void lightModel(GLenum name, const GLfloat* p) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !p) return;
    auto& l = s->lighting;
    switch (name) {
    case GL_LIGHT_MODEL_AMBIENT: l.modelAmbient = {p[0], p[1], p[2], p[3]}; break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: l.localViewer = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_TWO_SIDE:
        endBatch(*s);
        l.twoSide = p[0] != 0.0f;
        updateLitColors(*s);
        break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
        if (p[0] == static_cast<GLfloat>(GL_SINGLE_COLOR))
            l.separateSpecular = false;
        else if (p[0] == static_cast<GLfloat>(GL_SEPARATE_SPECULAR_COLOR))
            l.separateSpecular = true;
        else
            return setError(*s, GL_INVALID_ENUM);
        endBatch(*s);
        updateLitColors(*s);
        break;
    default: return setError(*s, GL_INVALID_ENUM);
    }
    endBatch(*s);
}

template <class T>
void lightModelv(GLenum name, const T* p) {
    if (!p) return;
    std::array<GLfloat, 4> f{};
    for (std::size_t i = 0; i < glcalls::lightModelCount(name, p); ++i) {
        f[i] = std::is_same_v<T, GLint> && name == GL_LIGHT_MODEL_AMBIENT ? intColor(static_cast<GLint>(p[i]))
                                                                          : static_cast<GLfloat>(p[i]);
    }
    lightModel(name, f.data());
}

void colorMaterial(GLenum face, GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return setError(*s, GL_INVALID_ENUM);
    if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
        mode != GL_AMBIENT_AND_DIFFUSE) {
        return setError(*s, GL_INVALID_ENUM);
    }
    endBatch(*s);
    s->colorMaterialFace = face;
    s->colorMaterialMode = mode;
    updateColorMaterial(*s);
}

// The values of a glGetLight query, or none for a name that is not one.
std::vector<float> lightValues(const LightSource& l, GLenum name) {
    auto v4 = [](const glm::vec4& v) { return std::vector<float>{v.x, v.y, v.z, v.w}; };
    switch (name) {
    case GL_AMBIENT: return v4(l.ambient);
    case GL_DIFFUSE: return v4(l.diffuse);
    case GL_SPECULAR: return v4(l.specular);
    case GL_POSITION: return v4(l.position);
    case GL_SPOT_DIRECTION: return {l.spotDirection.x, l.spotDirection.y, l.spotDirection.z};
    case GL_SPOT_EXPONENT: return {l.spotExponent};
    case GL_SPOT_CUTOFF: return {l.spotCutoff};
    case GL_CONSTANT_ATTENUATION: return {l.constantAttenuation};
    case GL_LINEAR_ATTENUATION: return {l.linearAttenuation};
    case GL_QUADRATIC_ATTENUATION: return {l.quadraticAttenuation};
    default: return {};
    }
}

std::vector<float> materialValues(const Material& m, GLenum name) {
    auto v4 = [](const glm::vec4& v) { return std::vector<float>{v.x, v.y, v.z, v.w}; };
    switch (name) {
    case GL_AMBIENT: return v4(m.ambient);
    case GL_DIFFUSE: return v4(m.diffuse);
    case GL_SPECULAR: return v4(m.specular);
    case GL_EMISSION: return v4(m.emission);
    case GL_SHININESS: return {m.shininess};
    case GL_COLOR_INDEXES: return {0.0f, 1.0f, 1.0f};
    default: return {};
    }
}

bool isColor(GLenum name) {
    return name == GL_AMBIENT || name == GL_DIFFUSE || name == GL_SPECULAR || name == GL_EMISSION;
}

// Answers into `out` converted by `convert(isColor, value)`.
template <class T, class Convert>
void getLight(GLenum lightName, GLenum name, T* out, Convert convert) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    const LightSource* l = lightOf(*s, lightName);
    if (!l) return;
    const std::vector<float> values = lightValues(*l, name);
    if (values.empty()) return setError(*s, GL_INVALID_ENUM);
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = convert(isColor(name), values[i]);
}

template <class T, class Convert>
void getMaterial(GLenum face, GLenum name, T* out, Convert convert) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    if (face != GL_FRONT && face != GL_BACK) return setError(*s, GL_INVALID_ENUM);
    storeFollowedColors(*s);
    const std::vector<float> values = materialValues(s->lighting.materials[face == GL_FRONT ? 0 : 1], name);
    if (values.empty()) return setError(*s, GL_INVALID_ENUM);
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = convert(isColor(name), values[i]);
}

// Colours as integers scale [-1, 1] to the integer range (FLOAT_TO_INT); a light's other values
// truncate, a material's (the shininess) round half away from zero (lroundf, measured).
GLint toInteger(bool color, float v) {
    return color ? static_cast<GLint>(2147483647.0 * static_cast<double>(v)) : static_cast<GLint>(v);
}
GLint toMaterialInteger(bool color, float v) {
    return color ? toInteger(color, v) : static_cast<GLint>(std::lround(v));
}
GLfloat asFloat(bool, float v) { return v; }

const EntryPoint kEntryPoints[] = {
    listed<gl::glLightf,
           +[](GLenum l, GLenum name, GLfloat v) { lightv(l, name, std::array<GLfloat, 4>{v}.data()); }>(),
    listed<gl::glLighti, +[](GLenum l, GLenum name,
                             GLint v) { lightv(l, name, std::array<GLfloat, 4>{static_cast<GLfloat>(v)}.data()); }>(),
    listed<gl::glLightfv, +[](GLenum l, GLenum name, const GLfloat* v) { lightv(l, name, v); }>(),
    listed<gl::glLightiv, +[](GLenum l, GLenum name, const GLint* v) { lightv(l, name, v); }>(),
    listed<gl::glMaterialf,
           +[](GLenum face, GLenum name, GLfloat v) { materialv(face, name, std::array<GLfloat, 4>{v}.data()); }>(),
    listed<gl::glMateriali,
           +[](GLenum face, GLenum name, GLint v) {
               materialv(face, name, std::array<GLfloat, 4>{static_cast<GLfloat>(v)}.data());
           }>(),
    listed<gl::glMaterialfv, +[](GLenum face, GLenum name, const GLfloat* v) { materialv(face, name, v); }>(),
    listed<gl::glMaterialiv, +[](GLenum face, GLenum name, const GLint* v) { materialv(face, name, v); }>(),
    listed<gl::glLightModelf, +[](GLenum name, GLfloat v) { lightModelv(name, std::array<GLfloat, 4>{v}.data()); }>(),
    listed<gl::glLightModeli,
           +[](GLenum name, GLint v) { lightModelv(name, std::array<GLfloat, 4>{static_cast<GLfloat>(v)}.data()); }>(),
    listed<gl::glLightModelfv, +[](GLenum name, const GLfloat* v) { lightModelv(name, v); }>(),
    listed<gl::glLightModeliv, +[](GLenum name, const GLint* v) { lightModelv(name, v); }>(),
    listed<gl::glColorMaterial, +[](GLenum face, GLenum mode) { colorMaterial(face, mode); }>(),
    listed<gl::glGetLightfv, +[](GLenum l, GLenum name, GLfloat* out) { getLight(l, name, out, asFloat); }>(),
    listed<gl::glGetLightiv, +[](GLenum l, GLenum name, GLint* out) { getLight(l, name, out, toInteger); }>(),
    listed<gl::glGetMaterialfv,
           +[](GLenum face, GLenum name, GLfloat* out) { getMaterial(face, name, out, asFloat); }>(),
    listed<gl::glGetMaterialiv,
           +[](GLenum face, GLenum name, GLint* out) { getMaterial(face, name, out, toMaterialInteger); }>(),
};

}  // namespace

std::span<const EntryPoint> lightingEntryPoints() { return kEntryPoints; }

bool setLightingCapability(Context::State& s, GLenum cap, bool enabled) {
    auto flag = [&](bool& field) {
        if (field != enabled) endBatch(s);
        field = enabled;
        return true;
    };
    if (cap == GL_LIGHTING) {
        flag(s.lightingEnabled);
        updateLitColors(s);
        return true;
    }
    if (cap == GL_NORMALIZE) return flag(s.lighting.normalize);
    if (cap == GL_RESCALE_NORMAL) return flag(s.lighting.rescaleNormal);
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + glrenderer::kMaxLights)
        return flag(s.lighting.lights[cap - GL_LIGHT0].enabled);
    if (cap == GL_COLOR_MATERIAL) {
        storeFollowedColors(s);
        flag(s.colorMaterialEnabled);
        updateColorMaterial(s);
        return true;
    }
    return false;
}

std::optional<bool> lightingCapability(const Context::State& s, GLenum cap) {
    if (cap == GL_LIGHTING) return s.lightingEnabled;
    if (cap == GL_NORMALIZE) return s.lighting.normalize;
    if (cap == GL_RESCALE_NORMAL) return s.lighting.rescaleNormal;
    if (cap == GL_COLOR_MATERIAL) return s.colorMaterialEnabled;
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + glrenderer::kMaxLights) return s.lighting.lights[cap - GL_LIGHT0].enabled;
    return std::nullopt;
}

namespace {

const glrenderer::VertexLighting& preparedLighting(Context::State& s) {
    if (s.lightingStale) {
        const StackMatrix& m = s.modelview.top();
        s.vertexLighting = glrenderer::VertexLighting(s.lighting, {m.matrix(), m.inverse(), m.lengthPreserving()});
        s.lightingStale = false;
        s.pipelineLightingStale = true;
    }
    return s.vertexLighting;
}

}  // namespace

void prepareLighting(Context::State& s) {
    if (!s.lightingEnabled) {
        s.pipelineLightingStale = true;
        return s.pipeline.setUnlit();
    }
    const glrenderer::VertexLighting& lighting = preparedLighting(s);
    if (!s.pipelineLightingStale) return;
    s.pipeline.setLighting(lighting);
    s.pipelineLightingStale = false;
}

void updateLitColors(Context::State& s) {
    s.draw.edit().twoSidedColors = s.lightingEnabled && s.lighting.twoSide;
    s.draw.edit().secondaryColors = s.lightingEnabled && s.lighting.separateSpecular;
}

void lightVertex(Context::State& s, glrenderer::Vertex& v, glrenderer::LightingOutputs* outputs) {
    preparedLighting(s).lightVertex(v, outputs, s.draw->twoSidedColors);
}

}  // namespace mygl
