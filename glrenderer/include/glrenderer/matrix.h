#pragma once
// 4x4 float matrices, column-major as GL stores them, and the reference's vertex transform.
#include <array>
#include <cstddef>

#include <glm/vec4.hpp>

namespace glrenderer {

using Matrix = std::array<float, 16>;

inline constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Element at `row`, `column`.
inline float& at(Matrix& m, int row, int column) { return m[static_cast<std::size_t>(column * 4 + row)]; }
inline float at(const Matrix& m, int row, int column) { return m[static_cast<std::size_t>(column * 4 + row)]; }

// The vertex transform of the reference's vertex stage: each product rounded, then summed left
// to right, nothing fused (measured: clip coordinates computed this way and sent with identity
// matrices give OSMesa the same depth buffer, bit for bit, as OSMesa's own transform).
inline glm::vec4 transform(const Matrix& m, const glm::vec4& v) {
    glm::vec4 r;
    for (int row = 0; row < 4; ++row) {
        r[row] = at(m, row, 0) * v.x + at(m, row, 1) * v.y + at(m, row, 2) * v.z + at(m, row, 3) * v.w;
    }
    return r;
}

}  // namespace glrenderer
