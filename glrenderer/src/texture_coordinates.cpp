#include "texture_coordinates.h"

namespace glrenderer {
namespace {

// Row `row` of `m` dotted with v as the reference's DP4 sums it: from the last component.
float dot4(const Matrix& m, int row, const glm::vec4& v) {
    const float x = v.x * at(m, row, 0), y = v.y * at(m, row, 1), z = v.z * at(m, row, 2), w = v.w * at(m, row, 3);
    return ((w + z) + y) + x;
}

}  // namespace

void textureCoordinates(std::span<const Vertex> vertices, const TextureState& texture, std::span<glm::vec4> out) {
    if (texture.identityMatrix) {
        for (std::size_t i = 0; i < vertices.size(); ++i) out[i] = vertices[i].texCoord;
        return;
    }
    const Matrix& m = texture.matrix;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec4& t = vertices[i].texCoord;
        out[i] = {dot4(m, 0, t), dot4(m, 1, t), dot4(m, 2, t), dot4(m, 3, t)};
    }
}

}  // namespace glrenderer
