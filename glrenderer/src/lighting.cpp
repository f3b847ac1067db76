// Lighting in the reference's arithmetic. Mesa turns the fixed-function state into a vertex
// program (main/ffvertex_prog.c) whose constants it computes on the CPU (program/prog_statevars.c,
// main/light.c); llvmpipe runs the program in float, every MAD a product then a sum (not fused),
// RSQ as 1 / sqrt(|x|), RCP as 1 / x, POW by gallivm's approximations. Each step below names
// the instruction it reproduces.
#include "glrenderer/lighting.h"

#include "glrenderer/saturate.h"

#include "cpu_features.h"
#include "exp2_approximation.h"
#include "simd_scalar.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glrenderer {
namespace {

using Matrix = std::array<float, 16>;

// DP3: the products summed from the last component to the first, as NIR splits the dot product.
float dot3(const glm::vec3& a, const glm::vec3& b) { return a.z * b.z + a.y * b.y + a.x * b.x; }

float reciprocalSqrt(float x) { return 1.0f / std::sqrt(std::fabs(x)); }

// The program's normalisation: DP3, RSQ, MUL.
glm::vec3 normalizeInProgram(const glm::vec3& v) { return v * reciprocalSqrt(dot3(v, v)); }

// Mesa's NORMALIZE_3FV on the CPU: the squares summed in order, left alone when zero.
glm::vec3 normalizeOnCpu(const glm::vec3& v) {
    float length = v.x * v.x + v.y * v.y + v.z * v.z;
    if (length == 0.0f) return v;
    length = 1.0f / std::sqrt(length);
    return v * length;
}

// Mesa's TRANSFORM_POINT: m * p, each row summed left to right.
glm::vec4 transformPoint(const Matrix& m, const glm::vec4& p) {
    glm::vec4 r;
    for (int i = 0; i < 4; ++i) r[i] = m[i] * p.x + m[4 + i] * p.y + m[8 + i] * p.z + m[12 + i] * p.w;
    return r;
}

// Mesa's TRANSFORM_NORMAL: transpose(m) * n, for the matrix that is the inverse of the one the
// normal is taken through.
glm::vec3 transformNormal(const Matrix& m, const glm::vec3& n) {
    return {n.x * m[0] + n.y * m[1] + n.z * m[2], n.x * m[4] + n.y * m[5] + n.z * m[6],
            n.x * m[8] + n.y * m[9] + n.z * m[10]};
}

glm::vec3 xyz(const glm::vec4& v) { return {v.x, v.y, v.z}; }

// llvmpipe's POW: exp2(log2(x) * y), each an approximation of its own (gallivm's
// lp_build_log2_safe, and lp_build_exp2 in exp2_approximation.h): minimax polynomials evaluated
// as even and odd halves, with LLVM's fmuladd, which is fused on CPUs with FMA and not on others.
float polynomial(float x, const double* coefficients, int count) {
    const float x2 = x * x;
    float even = 0.0f, odd = 0.0f;
    bool haveEven = false, haveOdd = false;
    for (int i = count - 1; i >= 0; --i) {
        const float c = static_cast<float>(coefficients[i]);
        float& term = i % 2 == 0 ? even : odd;
        bool& have = i % 2 == 0 ? haveEven : haveOdd;
        term = have ? ScalarLanes::multiplyAdd(x2, term, c) : c;
        have = true;
    }
    return haveOdd ? ScalarLanes::multiplyAdd(odd, x, even) : even;
}

float log2Approximation(float x) {
    static constexpr double kCoefficients[] = {2.88539009343309178325, 0.961791550404184197881, 0.577440339438736392009,
                                               0.403343858251329912514, 0.406718052498846252698};
    if (x < 0.0f || std::isnan(x)) return std::numeric_limits<float>::quiet_NaN();
    if (x == 0.0f) return -std::numeric_limits<float>::infinity();
    if (std::isinf(x)) return x;
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
    const float exponent = static_cast<float>(static_cast<int>((bits & 0x7f800000u) >> 23) - 127);
    const float mantissa = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);
    const float y = (mantissa - 1.0f) / (mantissa + 1.0f);
    const float z = y * y;
    return ScalarLanes::multiplyAdd(y, polynomial(z, kCoefficients, 5), exponent);
}

float power(float base, float exponent) {
    if (base == 0.0f) return 0.0f;
    const float x = log2Approximation(base) * exponent;
    return std::isnan(x) ? x : exp2Approximation<ScalarLanes>(x);
}

// LIT: (1, max(x, 0), x > 0 ? pow(max(y, 0), clamp(w, -128, 128)) : 0, 1), as NIR lowers it.
glm::vec4 lit(float x, float y, float w) {
    const float specular = 0.0f >= x ? 0.0f : power(std::max(y, 0.0f), std::clamp(w, -128.0f, 128.0f));
    return {1.0f, std::max(x, 0.0f), specular, 1.0f};
}

enum Property { kEmission, kAmbient, kDiffuse, kSpecular };

}  // namespace

VertexLighting::VertexLighting(const LightingState& state, const LightingModelview& modelview)
    : modelview_(modelview.matrix), inverse_(modelview.inverse), materials_(state.materials),
      follows_(state.colorMaterial), modelAmbient_(state.modelAmbient), normalize_(state.normalize),
      localViewer_(state.localViewer) {
    bool anyPositional = false;
    for (const LightSource& l : state.lights) anyPositional = anyPositional || (l.enabled && l.position.w != 0.0f);
    // main/light.c: eye coordinates when a light is positional, the viewer local, or the
    // modelview may change lengths; otherwise the lights go to object space instead.
    eyeSpace_ = anyPositional || state.localViewer || !modelview.lengthPreserving;
    // The normal scale (STATE_NORMAL_SCALE) rescales only eye-space normals; object space
    // multiplies by 1.
    rescale_ = eyeSpace_ && state.rescaleNormal && !state.normalize;
    if (rescale_ && !modelview.lengthPreserving) {
        const Matrix& inv = inverse_;
        float f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
        if (f < 1e-12f) f = 1.0f;
        normalScale_ = 1.0f / std::sqrt(f);
    }
    // One flag for both faces: the program has a specular term if either face may need it.
    shininessIsZero_ = materials_[0].shininess == 0.0f && (!state.twoSide || materials_[1].shininess == 0.0f);
    const glm::vec3 eyeZ = eyeSpace_ ? glm::vec3(0, 0, 1) : transformNormal(modelview_, {0, 0, 1});
    for (const LightSource& source : state.lights) {
        if (!source.enabled) continue;
        Light& l = lights_[static_cast<std::size_t>(lightCount_++)];
        l.positional = source.position.w != 0.0f;
        const glm::vec4 position = eyeSpace_ ? source.position : transformPoint(inverse_, source.position);
        l.position = l.positional ? xyz(position) : normalizeOnCpu(xyz(position));
        l.halfVector = normalizeOnCpu(normalizeOnCpu(xyz(position)) + eyeZ);
        l.spot = source.spotCutoff != 180.0f;
        const glm::vec3 spot = normalizeOnCpu(source.spotDirection);
        l.spotDirection = eyeSpace_ ? spot : normalizeOnCpu(transformNormal(modelview_, spot));
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

glm::vec4 VertexLighting::material(int face, int property, const glm::vec4& color) const {
    const ColorMaterial& f = follows_[static_cast<std::size_t>(face)];
    const Material& m = materials_[static_cast<std::size_t>(face)];
    switch (property) {
    case kEmission: return f.emission ? color : m.emission;
    case kAmbient: return f.ambient ? color : m.ambient;
    case kDiffuse: return f.diffuse ? color : m.diffuse;
    default: return f.specular ? color : m.specular;
    }
}

glm::vec3 VertexLighting::transformedNormal(const glm::vec3& normal) const {
    glm::vec3 n = normal;
    if (eyeSpace_) {  // DP3 with the rows of the inverse transpose
        const Matrix& inv = inverse_;
        n = {dot3(normal, {inv[0], inv[1], inv[2]}), dot3(normal, {inv[4], inv[5], inv[6]}),
             dot3(normal, {inv[8], inv[9], inv[10]})};
    }
    if (normalize_) return normalizeInProgram(n);
    if (rescale_) return n * normalScale_;
    return n;
}

glm::vec4 VertexLighting::light(const glm::vec4& object, const glm::vec3& normal, const glm::vec4& color,
                                int face) const {
    // The back face negates the dot products with the normal, which is exactly reversing it.
    const glm::vec3 n = face == 0 ? transformedNormal(normal) : -transformedNormal(normal);
    const glm::vec4 diffuseMaterial = material(face, kDiffuse, color);
    // The scene colour: model ambient * material ambient + emission, alpha the diffuse alpha.
    glm::vec4 sum = modelAmbient_ * material(face, kAmbient, color) + material(face, kEmission, color);
    sum.w = diffuseMaterial.w;
    const float alpha = sum.w;
    if (lightCount_ == 0) return sum;

    glm::vec3 eye{0.0f}, eyeDirection{0.0f};
    if (eyeSpace_) {
        const Matrix& m = modelview_;
        eye = xyz(transformPoint(m, object));
        if (localViewer_) eyeDirection = normalizeInProgram(eye);
    }
    const glm::vec4 ambientMaterial = material(face, kAmbient, color);
    const glm::vec4 specularMaterial = material(face, kSpecular, color);
    const float shininess = materials_[static_cast<std::size_t>(face)].shininess;
    for (int i = 0; i < lightCount_; ++i) {
        const Light& l = lights_[static_cast<std::size_t>(i)];
        glm::vec3 toLight = l.position;
        float inverseDistance = 0.0f;
        if (l.positional) {  // SUB, DP3, RSQ, MUL
            toLight = l.position - eye;
            inverseDistance = reciprocalSqrt(dot3(toLight, toLight));
            toLight = toLight * inverseDistance;
        }
        // Spot, then distance attenuation (calculate_light_attenuation).
        bool hasAttenuation = false;
        float attenuation = 1.0f;
        if (l.spot) {
            const float cosine = dot3(-toLight, l.spotDirection);
            const float inside = l.cosCutoff < cosine ? 1.0f : 0.0f;
            attenuation = inside * power(std::fabs(cosine), l.spotExponent);
            hasAttenuation = true;
        }
        if (l.attenuated) {
            const float distance = 1.0f / inverseDistance;  // RCP
            const glm::vec3 terms{inverseDistance * distance, distance, distance * distance};
            const float factor = 1.0f / dot3(l.attenuation, terms);
            attenuation = hasAttenuation ? factor * attenuation : factor;
            hasAttenuation = true;
        }
        glm::vec3 half{0.0f};
        if (!shininessIsZero_) {
            if (localViewer_) half = normalizeInProgram(toLight - eyeDirection);
            else if (!l.positional) half = l.halfVector;
            else half = normalizeInProgram(toLight + glm::vec3(0, 0, 1));
        }
        const float normalDotLight = dot3(n, toLight);
        const float normalDotHalf = shininessIsZero_ ? normalDotLight : dot3(n, half);
        const glm::vec4 ambient = l.ambient * ambientMaterial;
        const glm::vec4 diffuse = l.diffuse * diffuseMaterial;
        const glm::vec4 specular = l.specular * specularMaterial;
        glm::vec4 weights;  // LIT's y and z weigh the diffuse and specular products
        if (hasAttenuation) {
            weights = lit(normalDotLight, normalDotHalf, shininessIsZero_ ? normalDotLight : shininess) * attenuation;
            sum = weights.x * ambient + sum;
        } else {
            weights = shininessIsZero_ ? glm::vec4(1.0f, std::max(0.0f, normalDotLight), 0.0f < normalDotLight ? 1.0f : 0.0f, 1.0f)
                                       : lit(normalDotLight, normalDotHalf, shininess);
            sum = ambient + sum;
        }
        sum = weights.y * diffuse + sum;
        sum = weights.z * specular + sum;
    }
    sum.w = alpha;
    return sum;
}

void VertexLighting::lightVertex(Vertex& vertex, bool twoSided) const {
    const glm::vec4 color = vertex.color;
    vertex.color = saturate(light(vertex.position, vertex.normal, color));
    if (twoSided) vertex.backColor = saturate(light(vertex.position, vertex.normal, color, 1));
}

}  // namespace glrenderer
