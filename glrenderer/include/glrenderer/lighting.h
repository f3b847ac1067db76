#pragma once
// Fixed-function lighting (GL 1.x) as plain values, and the per-vertex computation in the
// reference's arithmetic (Mesa's fixed-function vertex program as llvmpipe runs it; see
// docs/reference-rules.md, "Lighting").
#include <array>
#include <span>

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
    std::array<Material, 2> materials;           // front, back
    std::array<ColorMaterial, 2> colorMaterial;  // front, back; all false when disabled
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

// A light as the vertex program sees it, prepared when the state changes.
struct PreparedLight {
    glm::vec3 position;    // a point (positional) or the normalized direction
    glm::vec3 halfVector;  // directional lights without a local viewer
    glm::vec3 spotDirection;
    float cosCutoff, spotExponent;
    glm::vec3 attenuation;                 // constant, linear, quadratic
    glm::vec4 ambient, diffuse, specular;  // the light's colours
    bool positional, spot, attenuated;
};

// The state prepared for lighting vertices, as the reference prepares it when state changes:
// the lighting space (object space when nothing needs eye coordinates), light vectors in that
// space, the materials and which of their colours follow the current colour.
struct PreparedLighting {
    std::array<PreparedLight, kMaxLights> lights{};
    int lightCount = 0;
    std::array<float, 16> modelview{};
    std::array<float, 16> inverse{};
    std::array<Material, 2> materials;
    std::array<ColorMaterial, 2> follows;
    glm::vec4 modelAmbient{0.0f};
    float normalScale = 1.0f;
    bool eyeSpace = false, normalize = false, rescale = false, localViewer = false;
    bool shininessIsZero = true;    // for both faces: no specular term in the program
    bool separateSpecular = false;  // the specular terms go to the secondary colours
};

// Lights vertices in the reference's arithmetic (docs/reference-rules.md, "Lighting"), several
// at a time in the widest lanes the CPU has, with the same bits at every width.
class VertexLighting {
public:
    VertexLighting() = default;
    VertexLighting(const LightingState& state, const LightingModelview& modelview);

    // Vertices lit in place: each one's colour (the current colour as given, unclamped) becomes
    // the lit colour and, with `twoSided`, its back colour the back face's (the back material,
    // the normal reversed), both clamped as the reference clamps vertex colours; with separate
    // specular, the specular terms go to the secondary colours instead, clamped likewise. The
    // back and secondary colours go to `outputs` (one per vertex; zeros for those the state
    // does not have), or nowhere when it is empty.
    void lightVertices(std::span<Vertex> vertices, std::span<LightingOutputs> outputs, bool twoSided) const;
    // One vertex, in one lane: the same bits without a block's work (`outputs` may be null).
    void lightVertex(Vertex& vertex, LightingOutputs* outputs, bool twoSided) const;
    const PreparedLighting& prepared() const { return prepared_; }

private:
    PreparedLighting prepared_;
};

}  // namespace glrenderer
