#pragma once
// 4x4 float matrices, column-major as GL stores them, with the reference's float arithmetic:
// products summed left to right, one rounding per operation (the build disables contraction).
#include <array>
#include <optional>

#include <glm/vec4.hpp>

namespace mygl {

using Matrix = std::array<float, 16>;

inline constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Element at `row`, `column`.
inline float& at(Matrix& m, int row, int column) { return m[static_cast<std::size_t>(column * 4 + row)]; }
inline float at(const Matrix& m, int row, int column) { return m[static_cast<std::size_t>(column * 4 + row)]; }

// a * b.
Matrix multiply(const Matrix& a, const Matrix& b);
// a * b for matrices whose bottom rows are taken as 0 0 0 1: the terms of the bottom rows are
// left out, and the product's bottom row is 0 0 0 1.
Matrix multiplyAffine(const Matrix& a, const Matrix& b);

// The matrices glRotate, glFrustum and glOrtho multiply onto the current one, built in float
// as the reference builds them. No rotation at all (nullopt) for a zero angle or an axis of
// length 1e-4 or less: the reference then leaves the matrix alone.
std::optional<Matrix> rotation(float angleDegrees, float x, float y, float z);
Matrix frustum(float left, float right, float bottom, float top, float nearVal, float farVal);
Matrix ortho(float left, float right, float bottom, float top, float nearVal, float farVal);

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

}  // namespace mygl
