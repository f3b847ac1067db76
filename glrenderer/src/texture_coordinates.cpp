#include "texture_coordinates.h"

#include <cmath>

#include <glm/vec2.hpp>

namespace glrenderer {
namespace {

// DP4 and DP3 as the reference sums them: from the last component.
float dot4(const glm::vec4& a, const glm::vec4& b) { return ((a.w * b.w + a.z * b.z) + a.y * b.y) + a.x * b.x; }
float dot3(const glm::vec3& a, const glm::vec3& b) { return (a.z * b.z + a.y * b.y) + a.x * b.x; }

// Row `row` of `m` dotted with v.
float dotRow(const Matrix& m, int row, const glm::vec4& v) {
    return dot4({at(m, row, 0), at(m, row, 1), at(m, row, 2), at(m, row, 3)}, v);
}

// The eye position: the modelview's columns times the coordinates, summed from the first.
glm::vec4 eyePosition(const Matrix& m, const glm::vec4& p) {
    glm::vec4 r;
    for (int i = 0; i < 4; ++i) r[i] = ((m[i] * p.x + m[4 + i] * p.y) + m[8 + i] * p.z) + m[12 + i] * p.w;
    return r;
}

// RSQ as llvmpipe computes it.
float reciprocalSqrt(float x) { return 1.0f / std::sqrt(std::fabs(x)); }

glm::vec3 normalizeInProgram(const glm::vec3& v) { return v * reciprocalSqrt(dot3(v, v)); }

// SPHERE_MAP's (s, t) for one vertex: the eye direction u reflected about the eye normal n,
// r = u - 2 (n.u) n, then r / m + 1/2 with m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2).
glm::vec2 sphereMap(const TextureGen& gen, const Matrix& modelview, const Vertex& v) {
    const glm::vec3 u = normalizeInProgram(glm::vec3(eyePosition(modelview, v.position)));
    const Matrix& inv = gen.inverseModelview;
    glm::vec3 n{dot3(v.normal, {inv[0], inv[1], inv[2]}), dot3(v.normal, {inv[4], inv[5], inv[6]}),
                dot3(v.normal, {inv[8], inv[9], inv[10]})};
    if (gen.normalize) n = normalizeInProgram(n);
    const float twoNu = dot3(n, u) + dot3(n, u);
    const glm::vec3 r = -n * twoNu + u;
    const glm::vec3 shifted{r.x, r.y, r.z + 1.0f};
    const float halfOverM = reciprocalSqrt(dot3(shifted, shifted)) * 0.5f;
    return {r.x * halfOverM + 0.5f, r.y * halfOverM + 0.5f};
}

glm::vec4 generated(const TextureGen& gen, const Matrix& modelview, const Vertex& v) {
    glm::vec4 t = v.texCoord;
    glm::vec4 eye{0.0f};
    bool eyeKnown = false;
    glm::vec2 sphere{0.0f};
    bool sphereKnown = false;
    for (int i = 0; i < 4; ++i) {
        if (!(gen.enabled >> i & 1u)) continue;
        switch (gen.mode[static_cast<std::size_t>(i)]) {
        case TexGenMode::ObjectLinear: t[i] = dot4(gen.objectPlane[static_cast<std::size_t>(i)], v.position); break;
        case TexGenMode::EyeLinear:
            if (!eyeKnown) eye = eyePosition(modelview, v.position), eyeKnown = true;
            t[i] = dot4(gen.eyePlane[static_cast<std::size_t>(i)], eye);
            break;
        case TexGenMode::SphereMap:
            if (!sphereKnown) sphere = sphereMap(gen, modelview, v), sphereKnown = true;
            t[i] = sphere[i];  // only S and T take SPHERE_MAP
            break;
        }
    }
    return t;
}

}  // namespace

void textureCoordinates(std::span<const Vertex> vertices, const TextureState& texture, const Matrix& modelview,
                        std::span<glm::vec4> out) {
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec4 t = texture.gen.enabled ? generated(texture.gen, modelview, vertices[i]) : vertices[i].texCoord;
        if (texture.identityMatrix) {
            out[i] = t;
        } else {
            const Matrix& m = texture.matrix;
            out[i] = {dotRow(m, 0, t), dotRow(m, 1, t), dotRow(m, 2, t), dotRow(m, 3, t)};
        }
    }
}

}  // namespace glrenderer
