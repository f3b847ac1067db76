#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace glrenderer {

// A vertex after the vertex stage: clip-space position and its RGBA colour. Eye-space position
// and normal are filled only when a culling method asks for them (Methods::needsEyeSpace).
struct ClipVertex {
    glm::vec4 position;
    glm::vec4 color;
    glm::vec4 backColor{0.0f};                                 // only with DrawState::twoSidedColors
    glm::vec3 secondaryColor{0.0f}, backSecondaryColor{0.0f};  // only with DrawState::secondaryColors
    bool edgeFlag = true;
    glm::vec3 eye{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float fogCoord = 0.0f;                       // only with fog: the eye-space distance (fog.h)
    glm::vec4 texCoord{0.0f, 0.0f, 0.0f, 1.0f};  // only with texturing: after the texture matrix
};

}  // namespace glrenderer
