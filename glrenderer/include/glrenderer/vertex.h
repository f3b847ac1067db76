#pragma once
#include <glm/vec4.hpp>

namespace glrenderer {

// A vertex after the modelview-projection transform: clip-space position and its RGBA color
// (floats, not yet clamped). The edge flag hides polygon edges in line and point mode.
struct Vertex {
    glm::vec4 position;
    glm::vec4 color;
    bool edgeFlag = true;
};

}  // namespace glrenderer
