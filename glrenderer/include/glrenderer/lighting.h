#pragma once
// Fixed-function lighting (GL 1.x) as plain values, and the per-vertex computation in the
// reference's arithmetic (Mesa's fixed-function vertex program as llvmpipe runs it; see
// docs/reference-rules.md, "Lighting").
#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "glrenderer/vertex.h"

namespace glrenderer {

struct LightSource {
    glm::vec4 ambient{0, 0, 0, 1};
    glm::vec4 diffuse{0, 0, 0, 1};
    glm::vec4 specular{0, 0, 0, 1};
    glm::vec4 position{0, 0, 1, 0};     // eye space (transformed when it was given)
    glm::vec3 spotDirection{0, 0, -1};  // eye space
    float spotExponent = 0, spotCutoff = 180;
    float constantAttenuation = 1, linearAttenuation = 0, quadraticAttenuation = 0;
    bool enabled = false;
};

struct Material {
    glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1};
    glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1};
    glm::vec4 specular{0, 0, 0, 1};
    glm::vec4 emission{0, 0, 0, 1};
    float shininess = 0;
};

inline constexpr int kMaxLights = 8;

// Which material colours follow the current colour (glColorMaterial), per face.
struct ColorMaterial {
    bool emission = false, ambient = false, diffuse = false, specular = false;
};

struct LightingState {
    std::array<LightSource, kMaxLights> lights;
    glm::vec4 modelAmbient{0.2f, 0.2f, 0.2f, 1};
    bool localViewer = false;
    bool twoSide = false;
    bool separateSpecular = false;
    std::array<Material, 2> materials;               // front, back
    std::array<ColorMaterial, 2> colorMaterial;       // front, back; all false when disabled
    bool normalize = false, rescaleNormal = false;
};

// The modelview as the reference's lighting sees it: the matrix (column-major), its inverse as
// the reference computes it, and whether the reference knows it to preserve lengths (only
// rotations and translations applied).
struct LightingModelview {
    std::array<float, 16> matrix;
    std::array<float, 16> inverse;
    bool lengthPreserving;
};

// The state prepared for lighting vertices, as the reference prepares it when state changes:
// the lighting space (object space when nothing needs eye coordinates), light vectors in that
// space, products of light and material colours.
class VertexLighting {
public:
    VertexLighting() = default;
    VertexLighting(const LightingState& state, const LightingModelview& modelview);

    // The lit colour (not yet clamped) of a vertex at `object` with the object-space normal
    // `normal`; `color`: the current colour, for the material colours that follow it. `face`
    // 1 lights the back face (back material, the normal reversed) for two-sided lighting.
    glm::vec4 light(const glm::vec4& object, const glm::vec3& normal, const glm::vec4& color, int face = 0) const;
    // A vertex lit in place: its colour (the current colour as given, unclamped) becomes the
    // lit colour and, with `twoSided`, its back colour the back face's, both clamped as the
    // reference clamps vertex colours.
    void lightVertex(Vertex& vertex, bool twoSided) const;

private:
    struct Light {
        glm::vec3 position;     // a point (positional) or the normalized direction
        glm::vec3 halfVector;   // directional lights without a local viewer
        glm::vec3 spotDirection;
        float cosCutoff, spotExponent;
        glm::vec3 attenuation;  // constant, linear, quadratic
        glm::vec4 ambient, diffuse, specular;  // the light's colours
        bool positional, spot, attenuated;
    };
    glm::vec3 transformedNormal(const glm::vec3& normal) const;
    glm::vec4 material(int face, int property, const glm::vec4& color) const;

    std::array<Light, kMaxLights> lights_{};
    int lightCount_ = 0;
    std::array<float, 16> modelview_{};
    std::array<float, 16> inverse_{};
    std::array<Material, 2> materials_;
    std::array<ColorMaterial, 2> follows_;
    glm::vec4 modelAmbient_{0.0f};
    float normalScale_ = 1.0f;
    bool eyeSpace_ = false, normalize_ = false, rescale_ = false, localViewer_ = false;
    bool shininessIsZero_ = true;
};

}  // namespace glrenderer
