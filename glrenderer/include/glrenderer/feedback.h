#pragma once
// GL_FEEDBACK: what the pipeline hands back instead of pixels, as the reference's draw module
// hands it to its feedback stage: points, lines and triangles after clipping and culling, in
// window coordinates.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace glrenderer {

struct FeedbackVertex {
    float x = 0, y = 0, z = 0;  // window coordinates, y up (GL's orientation)
    float w = 1;                // the clip-space w
    glm::vec4 color{0.0f};
};

struct FeedbackPrimitive {
    enum class Kind : std::uint8_t { Point, Line, LineReset, Polygon };
    Kind kind = Kind::Point;
    std::array<FeedbackVertex, 3> vertices{};  // 1, 2 or 3 of them, by kind

    int vertexCount() const { return kind == Kind::Point ? 1 : kind == Kind::Polygon ? 3 : 2; }
};

using FeedbackPrimitives = std::vector<FeedbackPrimitive>;

}  // namespace glrenderer
