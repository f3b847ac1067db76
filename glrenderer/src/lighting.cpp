// Lighting prepared as the reference prepares it when state changes (main/light.c,
// program/prog_statevars.c), and the per-vertex program (lighting_lanes.h) run in the widest
// lanes this CPU has.
#include "glrenderer/lighting.h"

#include <algorithm>
#include <cmath>

#include "cpu_features.h"
#include "lighting_lanes.h"
#include "lighting_paths.h"
#include "simd_scalar.h"

namespace glrenderer {
namespace {

using Matrix = std::array<float, 16>;

// Mesa's NORMALIZE_3FV on the CPU: the squares summed in order, left alone when zero.
glm::vec3 normalizeOnCpu(const glm::vec3& v) {
    float length = v.x * v.x + v.y * v.y + v.z * v.z;
    if (length == 0.0f) return v;
    length = 1.0f / std::sqrt(length);
    return v * length;
}

// Mesa's TRANSFORM_POINT (the program's, lighting_lanes.h), x, y and z.
glm::vec3 transformPoint(const Matrix& m, const glm::vec4& p) {
    using Lanes = LightingLanes<ScalarLanes>;
    const Lanes::Vec3 r = Lanes::transformPoint(m, Lanes::broadcast(p));
    return {r.x, r.y, r.z};
}

// Mesa's TRANSFORM_NORMAL: transpose(m) * n, for the matrix that is the inverse of the one the
// normal is taken through.
glm::vec3 transformNormal(const Matrix& m, const glm::vec3& n) {
    return {n.x * m[0] + n.y * m[1] + n.z * m[2], n.x * m[4] + n.y * m[5] + n.z * m[6],
            n.x * m[8] + n.y * m[9] + n.z * m[10]};
}

}  // namespace

VertexLighting::VertexLighting(const LightingState& state, const LightingModelview& modelview) {
    PreparedLighting& p = prepared_;
    p.modelview = modelview.matrix;
    p.inverse = modelview.inverse;
    p.materials = state.materials;
    p.follows = state.colorMaterial;
    p.modelAmbient = state.modelAmbient;
    p.normalize = state.normalize;
    p.localViewer = state.localViewer;
    p.separateSpecular = state.separateSpecular;
    bool anyPositional = false;
    for (const LightSource& l : state.lights) anyPositional = anyPositional || (l.enabled && l.position.w != 0.0f);
    // main/light.c: eye coordinates when a light is positional, the viewer local, or the
    // modelview may change lengths; otherwise the lights go to object space instead.
    p.eyeSpace = anyPositional || state.localViewer || !modelview.lengthPreserving;
    // The normal scale (STATE_NORMAL_SCALE) rescales only eye-space normals; object space
    // multiplies by 1.
    p.rescale = p.eyeSpace && state.rescaleNormal && !state.normalize;
    if (p.rescale && !modelview.lengthPreserving) {
        const Matrix& inv = p.inverse;
        float f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
        if (f < 1e-12f) f = 1.0f;
        p.normalScale = 1.0f / std::sqrt(f);
    }
    // One flag for both faces: the program has a specular term if either face may need it.
    p.shininessIsZero = p.materials[0].shininess == 0.0f && (!state.twoSide || p.materials[1].shininess == 0.0f);
    const glm::vec3 eyeZ = p.eyeSpace ? glm::vec3(0, 0, 1) : transformNormal(p.modelview, {0, 0, 1});
    for (const LightSource& source : state.lights) {
        if (!source.enabled) continue;
        PreparedLight& l = p.lights[static_cast<std::size_t>(p.lightCount++)];
        l.positional = source.position.w != 0.0f;
        const glm::vec3 position = p.eyeSpace ? glm::vec3(source.position) : transformPoint(p.inverse, source.position);
        l.position = l.positional ? position : normalizeOnCpu(position);
        l.halfVector = normalizeOnCpu(normalizeOnCpu(position) + eyeZ);
        l.spot = source.spotCutoff != 180.0f;
        const glm::vec3 spot = normalizeOnCpu(source.spotDirection);
        l.spotDirection = p.eyeSpace ? spot : normalizeOnCpu(transformNormal(p.modelview, spot));
        l.cosCutoff = std::max(static_cast<float>(std::cos(source.spotCutoff * M_PI / 180.0)), 0.0f);
        l.spotExponent = source.spotExponent;
        l.attenuation = {source.constantAttenuation, source.linearAttenuation, source.quadraticAttenuation};
        l.attenuated = l.positional && (source.constantAttenuation != 1.0f || source.linearAttenuation != 0.0f ||
                                        source.quadraticAttenuation != 0.0f);
        l.ambient = source.ambient;
        l.diffuse = source.diffuse;
        l.specular = source.specular;
    }
}

void lightVerticesScalar(const PreparedLighting& lighting, std::span<Vertex> vertices,
                         std::span<LightingOutputs> outputs, bool twoSided) {
    LightingProgram<ScalarLanes>(lighting).lightVertices(vertices, outputs, twoSided);
}

void VertexLighting::lightVertices(std::span<Vertex> vertices, std::span<LightingOutputs> outputs,
                                   bool twoSided) const {
    switch (widestLanes()) {
    case LaneWidth::Avx512: return lightVerticesAvx512(prepared_, vertices, outputs, twoSided);
    case LaneWidth::Avx2: return lightVerticesAvx2(prepared_, vertices, outputs, twoSided);
    case LaneWidth::Scalar: break;
    }
    lightVerticesScalar(prepared_, vertices, outputs, twoSided);
}

void VertexLighting::lightVertex(Vertex& vertex, LightingOutputs* outputs, bool twoSided) const {
    lightVerticesScalar(prepared_, {&vertex, 1}, outputs ? std::span(outputs, 1) : std::span<LightingOutputs>{},
                        twoSided);
}

}  // namespace glrenderer
