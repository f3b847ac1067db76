#pragma once
// 4x4 float matrices, column-major as GL stores them, with the reference's float arithmetic:
// products summed left to right, one rounding per operation (the build disables contraction).
#include <array>
#include <optional>

#include <glm/vec4.hpp>
#include <glrenderer/matrix.h>

namespace mygl {

using glrenderer::at;
using glrenderer::kIdentity;
using glrenderer::Matrix;
using glrenderer::transform;

// a * b.
Matrix multiply(const Matrix& a, const Matrix& b);
// a * b for matrices whose bottom rows are taken as 0 0 0 1: the terms of the bottom rows are
// left out, and the product's bottom row is 0 0 0 1.
Matrix multiplyAffine(const Matrix& a, const Matrix& b);

// Mesa's _mesa_transform_vector: the row vector v times m, each component summed left to right
// (planes taken to eye space: glClipPlane, glTexGen's eye planes).
glm::vec4 timesMatrix(const glm::vec4& v, const Matrix& m);

// The matrices glRotate, glFrustum and glOrtho multiply onto the current one, built in float
// as the reference builds them. No rotation at all (nullopt) for a zero angle or an axis of
// length 1e-4 or less: the reference then leaves the matrix alone.
std::optional<Matrix> rotation(float angleDegrees, float x, float y, float z);
Matrix frustum(float left, float right, float bottom, float top, float nearVal, float farVal);
Matrix ortho(float left, float right, float bottom, float top, float nearVal, float farVal);

}  // namespace mygl
