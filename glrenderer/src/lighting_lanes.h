#pragma once
// Per-vertex lighting in the reference's arithmetic, written once over a lane type L
// (simd_scalar.h, simd_avx2.h, simd_avx512.h): L::kCount vertices at a time. Mesa turns the
// fixed-function state into a vertex program (main/ffvertex_prog.c) that llvmpipe runs in float,
// every MAD a product then a sum (not fused), RSQ as 1 / sqrt(|x|), RCP as 1 / x, POW by
// gallivm's approximations; each step below names the instruction it reproduces. Every lane
// performs the scalar operations in the same order, so the colours do not depend on the width.
// Included only by the files that compile it for one width (lighting_*.cpp).
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <span>

#include "glrenderer/invariant.h"
#include "glrenderer/lighting.h"

#include "exp2_approximation.h"

namespace glrenderer {

template <class L>
struct LightingLanes {
    using Float = typename L::Float;
    using Mask = typename L::Mask;

    struct Vec3 {
        Float x, y, z;
    };
    struct Vec4 {
        Float x, y, z, w;
    };

    static Vec3 broadcast(const glm::vec3& v) { return {L::floats(v.x), L::floats(v.y), L::floats(v.z)}; }
    static Vec4 broadcast(const glm::vec4& v) {
        return {L::floats(v.x), L::floats(v.y), L::floats(v.z), L::floats(v.w)};
    }
    static Vec3 add(const Vec3& a, const Vec3& b) { return {L::add(a.x, b.x), L::add(a.y, b.y), L::add(a.z, b.z)}; }
    static Vec3 sub(const Vec3& a, const Vec3& b) { return {L::sub(a.x, b.x), L::sub(a.y, b.y), L::sub(a.z, b.z)}; }
    static Vec3 scale(const Vec3& v, Float s) { return {L::mul(v.x, s), L::mul(v.y, s), L::mul(v.z, s)}; }
    static Vec3 negate(const Vec3& v) {
        const Float zero = L::floats(-0.0f);  // -x as a sign flip: x - 0 would change -0 and NaN signs
        return {L::fromBits(L::bitXor(L::bitsOf(v.x), L::bitsOf(zero))),
                L::fromBits(L::bitXor(L::bitsOf(v.y), L::bitsOf(zero))),
                L::fromBits(L::bitXor(L::bitsOf(v.z), L::bitsOf(zero)))};
    }
    static Vec4 mul(const Vec4& a, const Vec4& b) {
        return {L::mul(a.x, b.x), L::mul(a.y, b.y), L::mul(a.z, b.z), L::mul(a.w, b.w)};
    }
    // s * a + b, a product then a sum per component.
    static Vec4 scaleAdd(Float s, const Vec4& a, const Vec4& b) {
        return {L::add(L::mul(s, a.x), b.x), L::add(L::mul(s, a.y), b.y), L::add(L::mul(s, a.z), b.z),
                L::add(L::mul(s, a.w), b.w)};
    }
    static Vec4 sum(const Vec4& a, const Vec4& b) {
        return {L::add(a.x, b.x), L::add(a.y, b.y), L::add(a.z, b.z), L::add(a.w, b.w)};
    }

    // DP3: the products summed from the last component to the first, as NIR splits the dot product.
    static Float dot3(const Vec3& a, const Vec3& b) {
        return L::add(L::add(L::mul(a.z, b.z), L::mul(a.y, b.y)), L::mul(a.x, b.x));
    }
    static Float reciprocalSqrt(Float x) { return L::div(L::floats(1.0f), L::sqrt(L::abs(x))); }
    // The program's normalisation: DP3, RSQ, MUL.
    static Vec3 normalizeInProgram(const Vec3& v) { return scale(v, reciprocalSqrt(dot3(v, v))); }

    // gallivm's lp_build_log2_safe: the exponent bits plus a minimax polynomial of the mantissa,
    // evaluated as even and odd halves with LLVM's fmuladd (fused on CPUs with FMA).
    static Float log2Approximation(Float x) {
        static constexpr double kCoefficients[] = {2.88539009343309178325, 0.961791550404184197881,
                                                   0.577440339438736392009, 0.403343858251329912514,
                                                   0.406718052498846252698};
        const auto c = [](int i) { return L::floats(static_cast<float>(kCoefficients[i])); };
        const auto bits = L::bitsOf(x);
        const Float exponent =
            L::toFloat(L::sub(L::shiftRight(L::bitAnd(bits, L::ints(0x7f800000)), 23), L::ints(127)));
        const Float mantissa = L::fromBits(L::bitOr(L::bitAnd(bits, L::ints(0x007fffff)), L::ints(0x3f800000)));
        const Float y = L::div(L::sub(mantissa, L::floats(1.0f)), L::add(mantissa, L::floats(1.0f)));
        const Float z = L::mul(y, y), z2 = L::mul(z, z);
        const Float even = L::multiplyAdd(z2, L::multiplyAdd(z2, c(4), c(2)), c(0));
        const Float odd = L::multiplyAdd(z2, c(3), c(1));
        Float log2 = L::multiplyAdd(y, L::multiplyAdd(odd, z, even), exponent);
        // Outside the positive finite numbers: NaN below zero, -inf at zero, +inf at +inf.
        const Float infinity = L::floats(std::numeric_limits<float>::infinity());
        log2 = L::select(L::equal(x, infinity), infinity, log2);
        log2 = L::select(L::equal(x, L::floats(0.0f)), L::floats(-std::numeric_limits<float>::infinity()), log2);
        const Mask invalid = L::either(L::lessThan(x, L::floats(0.0f)), L::isNan(x));
        return L::select(invalid, L::floats(std::numeric_limits<float>::quiet_NaN()), log2);
    }

    // llvmpipe's POW: exp2(log2(x) * y), 0 where x is 0.
    static Float power(Float base, Float exponent) {
        const Float x = L::mul(log2Approximation(base), exponent);
        const Float result = L::select(L::isNan(x), x, exp2Approximation<L>(x));
        return L::select(L::equal(base, L::floats(0.0f)), L::floats(0.0f), result);
    }

    // LIT's z: x > 0 ? pow(max(y, 0), clamp(w, -128, 128)) : 0, as NIR lowers it. A NaN x or y
    // gives 0 (the comparison fails; the max takes the other operand).
    static Float litSpecular(Float x, Float y, Float w) {
        const Float low = L::floats(-128.0f), high = L::floats(128.0f);
        const Float clamped = L::select(L::lessThan(w, low), low, L::select(L::lessThan(high, w), high, w));
        const Float specular = power(L::max(y, L::floats(0.0f)), clamped);
        return L::select(L::lessThan(L::floats(0.0f), x), specular, L::floats(0.0f));
    }

    // Mesa's TRANSFORM_POINT: m * p, each row summed left to right.
    static Vec3 transformPoint(const std::array<float, 16>& m, const Vec4& p) {
        const auto row = [&](int i) {
            return L::add(L::add(L::add(L::mul(L::floats(m[i]), p.x), L::mul(L::floats(m[4 + i]), p.y)),
                                 L::mul(L::floats(m[8 + i]), p.z)),
                          L::mul(L::floats(m[12 + i]), p.w));
        };
        return {row(0), row(1), row(2)};
    }
};

// The lanes of one block of vertices, read from and written back to the vertex records.
template <class L>
struct VertexBlock {
    using Lanes = LightingLanes<L>;
    static constexpr int kCount = L::kCount;
    alignas(64) float position[4][kCount], normal[3][kCount], color[4][kCount];

    // Vertices first .. first + count (count <= kCount); the lanes beyond repeat the last one.
    void read(std::span<const Vertex> vertices) {
        for (int lane = 0; lane < kCount; ++lane) {
            const Vertex& v = vertices[std::min<std::size_t>(static_cast<std::size_t>(lane), vertices.size() - 1)];
            for (int c = 0; c < 4; ++c) position[c][lane] = v.position[c], color[c][lane] = v.color[c];
            for (int c = 0; c < 3; ++c) normal[c][lane] = v.normal[c];
        }
    }
    typename Lanes::Vec4 positions() const {
        return {load(position[0]), load(position[1]), load(position[2]), load(position[3])};
    }
    typename Lanes::Vec3 normals() const { return {load(normal[0]), load(normal[1]), load(normal[2])}; }
    typename Lanes::Vec4 colors() const { return {load(color[0]), load(color[1]), load(color[2]), load(color[3])}; }

    static typename L::Float load(const float* lanes) { return L::loadFloats(lanes); }
};

template <class L>
class LightingProgram {
public:
    using Lanes = LightingLanes<L>;
    using Float = typename L::Float;
    using Vec3 = typename Lanes::Vec3;
    using Vec4 = typename Lanes::Vec4;

    explicit LightingProgram(const PreparedLighting& p) : p_(p) {}

    void lightVertices(std::span<Vertex> vertices, std::span<LightingOutputs> outputs, bool twoSided) const {
        MYGL_INVARIANT(outputs.empty() || outputs.size() == vertices.size());
        if (outputs.size() != vertices.size()) outputs = {};
        VertexBlock<L> block;
        alignas(64) float lit[2][4][L::kCount], litSecondary[2][4][L::kCount];
        for (std::size_t first = 0; first < vertices.size(); first += L::kCount) {
            const std::size_t aheadEnd = std::min(first + kVertexFetchAhead + L::kCount, vertices.size());
            for (std::size_t ahead = first + kVertexFetchAhead; ahead < aheadEnd; ++ahead)
                __builtin_prefetch(&vertices[ahead]);
            const std::span<Vertex> part =
                vertices.subspan(first, std::min<std::size_t>(L::kCount, vertices.size() - first));
            block.read(part);
            const Vec4 position = block.positions(), color = block.colors();
            const Vec3 normal = transformedNormal(block.normals());
            for (int face = 0; face < (twoSided ? 2 : 1); ++face) {
                const LitColors c = light(position, face == 0 ? normal : Lanes::negate(normal), color, face);
                store(lit[face], saturate(c.primary));
                if (p_.separateSpecular) store(litSecondary[face], saturate(c.secondary));
            }
            for (std::size_t lane = 0; lane < part.size(); ++lane) {
                for (int c = 0; c < 4; ++c) part[lane].color[c] = lit[0][c][lane];
                if (outputs.empty()) continue;
                LightingOutputs& o = outputs[first + lane];
                for (int c = 0; c < 4; ++c) o.backColor[c] = twoSided ? lit[1][c][lane] : 0.0f;
                for (int c = 0; c < 3; ++c) {
                    o.secondaryColor[c] = p_.separateSpecular ? litSecondary[0][c][lane] : 0.0f;
                    o.backSecondaryColor[c] = p_.separateSpecular && twoSided ? litSecondary[1][c][lane] : 0.0f;
                }
            }
        }
    }

private:
    // A face's lit colours, not yet clamped: with separate specular the specular terms are in
    // `secondary` (which starts at 0), otherwise in `primary`.
    struct LitColors {
        Vec4 primary, secondary;
    };

    static void store(float (&lanes)[4][L::kCount], const Vec4& c) {
        L::storeFloats(lanes[0], c.x), L::storeFloats(lanes[1], c.y);
        L::storeFloats(lanes[2], c.z), L::storeFloats(lanes[3], c.w);
    }

    // The reference's vertex stage saturates colours with max(0, c) then min(., 1), where a NaN
    // operand gives way to the second one: NaN stays NaN, then becomes 1 (saturate.h).
    static Vec4 saturate(const Vec4& c) {
        const auto one = [](Float v) { return L::min(L::max(L::floats(0.0f), v), L::floats(1.0f)); };
        return {one(c.x), one(c.y), one(c.z), one(c.w)};
    }

    Vec3 transformedNormal(const Vec3& normal) const {
        Vec3 n = normal;
        if (p_.eyeSpace) {  // DP3 with the rows of the inverse transpose
            const std::array<float, 16>& inv = p_.inverse;
            n = {Lanes::dot3(normal, Lanes::broadcast(glm::vec3(inv[0], inv[1], inv[2]))),
                 Lanes::dot3(normal, Lanes::broadcast(glm::vec3(inv[4], inv[5], inv[6]))),
                 Lanes::dot3(normal, Lanes::broadcast(glm::vec3(inv[8], inv[9], inv[10])))};
        }
        if (p_.normalize) return Lanes::normalizeInProgram(n);
        if (p_.rescale) return Lanes::scale(n, L::floats(p_.normalScale));
        return n;
    }

    enum Property { kEmission, kAmbient, kDiffuse, kSpecular };

    // A material colour of `face`: the current colour where it follows it (glColorMaterial).
    Vec4 material(int face, Property property, const Vec4& color) const {
        const ColorMaterial& f = p_.follows[static_cast<std::size_t>(face)];
        const Material& m = p_.materials[static_cast<std::size_t>(face)];
        switch (property) {
        case kEmission: return f.emission ? color : Lanes::broadcast(m.emission);
        case kAmbient: return f.ambient ? color : Lanes::broadcast(m.ambient);
        case kDiffuse: return f.diffuse ? color : Lanes::broadcast(m.diffuse);
        case kSpecular: break;
        }
        return f.specular ? color : Lanes::broadcast(m.specular);
    }

    // The lit colours of the vertices at `object` with the transformed normal `n` (reversed for
    // the back face).
    LitColors light(const Vec4& object, const Vec3& n, const Vec4& color, int face) const {
        const Vec4 diffuseMaterial = material(face, kDiffuse, color);
        const Vec4 ambientMaterial = material(face, kAmbient, color);
        // The scene colour: model ambient * material ambient + emission, alpha the diffuse alpha.
        LitColors lit{Lanes::sum(Lanes::mul(Lanes::broadcast(p_.modelAmbient), ambientMaterial),
                                 material(face, kEmission, color)),
                      Lanes::broadcast(glm::vec4(0.0f))};
        const Float alpha = diffuseMaterial.w;
        if (p_.lightCount > 0) {
            Vec3 eye{}, eyeDirection{};
            if (p_.eyeSpace) {
                eye = Lanes::transformPoint(p_.modelview, object);
                if (p_.localViewer) eyeDirection = Lanes::normalizeInProgram(eye);
            }
            const Vec4 specularMaterial = material(face, kSpecular, color);
            const Float shininess = L::floats(p_.materials[static_cast<std::size_t>(face)].shininess);
            for (int i = 0; i < p_.lightCount; ++i) {
                lit = addLight(p_.lights[static_cast<std::size_t>(i)], n, eye, eyeDirection, shininess,
                               {ambientMaterial, diffuseMaterial, specularMaterial}, lit);
            }
        }
        lit.primary.w = alpha;
        return lit;
    }

    struct Materials {
        Vec4 ambient, diffuse, specular;
    };

    // One light's terms added to `lit`.
    LitColors addLight(const PreparedLight& l, const Vec3& n, const Vec3& eye, const Vec3& eyeDirection,
                       Float shininess, const Materials& material, LitColors lit) const {
        Vec4& sum = lit.primary;
        Vec3 toLight = Lanes::broadcast(l.position);
        Float inverseDistance = L::floats(0.0f);
        if (l.positional) {  // SUB, DP3, RSQ, MUL
            toLight = Lanes::sub(toLight, eye);
            inverseDistance = Lanes::reciprocalSqrt(Lanes::dot3(toLight, toLight));
            toLight = Lanes::scale(toLight, inverseDistance);
        }
        // Spot, then distance attenuation (calculate_light_attenuation).
        bool hasAttenuation = false;
        Float attenuation = L::floats(1.0f);
        if (l.spot) {
            const Float cosine = Lanes::dot3(Lanes::negate(toLight), Lanes::broadcast(l.spotDirection));
            const Float inside =
                L::select(L::lessThan(L::floats(l.cosCutoff), cosine), L::floats(1.0f), L::floats(0.0f));
            attenuation = L::mul(inside, Lanes::power(L::abs(cosine), L::floats(l.spotExponent)));
            hasAttenuation = true;
        }
        if (l.attenuated) {
            const Float distance = L::div(L::floats(1.0f), inverseDistance);  // RCP
            const Vec3 terms{L::mul(inverseDistance, distance), distance, L::mul(distance, distance)};
            const Float factor = L::div(L::floats(1.0f), Lanes::dot3(Lanes::broadcast(l.attenuation), terms));
            attenuation = hasAttenuation ? L::mul(factor, attenuation) : factor;
            hasAttenuation = true;
        }
        const Float normalDotLight = Lanes::dot3(n, toLight);
        Float normalDotHalf = normalDotLight;
        if (!p_.shininessIsZero) {
            Vec3 half;
            if (p_.localViewer)
                half = Lanes::normalizeInProgram(Lanes::sub(toLight, eyeDirection));
            else if (!l.positional)
                half = Lanes::broadcast(l.halfVector);
            else
                half = Lanes::normalizeInProgram(Lanes::add(toLight, Lanes::broadcast(glm::vec3(0, 0, 1))));
            normalDotHalf = Lanes::dot3(n, half);
        }
        const Vec4 ambient = Lanes::mul(Lanes::broadcast(l.ambient), material.ambient);
        const Vec4 diffuse = Lanes::mul(Lanes::broadcast(l.diffuse), material.diffuse);
        const Vec4 specular = Lanes::mul(Lanes::broadcast(l.specular), material.specular);
        // LIT's y and z weigh the diffuse and specular products.
        const Float zero = L::floats(0.0f), one = L::floats(1.0f);
        Float diffuseWeight, specularWeight;
        if (hasAttenuation) {
            const Float exponent = p_.shininessIsZero ? normalDotLight : shininess;
            diffuseWeight = L::mul(L::max(normalDotLight, zero), attenuation);  // LIT's y: NaN gives 0
            specularWeight = L::mul(Lanes::litSpecular(normalDotLight, normalDotHalf, exponent), attenuation);
            sum = Lanes::scaleAdd(attenuation, ambient, sum);  // LIT's x (1) times the attenuation
        } else {
            if (p_.shininessIsZero) {
                diffuseWeight = L::max(normalDotLight, zero);
                specularWeight = L::select(L::lessThan(zero, normalDotLight), one, zero);
            } else {
                diffuseWeight = L::max(normalDotLight, zero);  // LIT's y: NaN gives 0
                specularWeight = Lanes::litSpecular(normalDotLight, normalDotHalf, shininess);
            }
            sum = Lanes::sum(ambient, sum);
        }
        sum = Lanes::scaleAdd(diffuseWeight, diffuse, sum);
        Vec4& specularSum = p_.separateSpecular ? lit.secondary : sum;
        specularSum = Lanes::scaleAdd(specularWeight, specular, specularSum);
        return lit;
    }

    const PreparedLighting& p_;
};

}  // namespace glrenderer
