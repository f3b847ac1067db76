#include "matrix_math.h"

#include <cmath>

namespace mygl {

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix p;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            at(p, i, j) = at(a, i, 0) * at(b, 0, j) + at(a, i, 1) * at(b, 1, j) + at(a, i, 2) * at(b, 2, j) +
                          at(a, i, 3) * at(b, 3, j);
        }
    }
    return p;
}

Matrix multiplyAffine(const Matrix& a, const Matrix& b) {
    Matrix p = kIdentity;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            at(p, i, j) = at(a, i, 0) * at(b, 0, j) + at(a, i, 1) * at(b, 1, j) + at(a, i, 2) * at(b, 2, j);
        }
        at(p, i, 3) = at(a, i, 0) * at(b, 0, 3) + at(a, i, 1) * at(b, 1, 3) + at(a, i, 2) * at(b, 2, 3) + at(a, i, 3);
    }
    return p;
}

std::optional<Matrix> rotation(float angleDegrees, float x, float y, float z) {
    if (angleDegrees == 0.0f) return std::nullopt;
    // The angle goes to radians in double, then sine and cosine in float, as the reference does.
    const float radians = static_cast<float>(static_cast<double>(angleDegrees) * M_PI / 180.0);
    float s = std::sin(radians);
    const float c = std::cos(radians);
    Matrix m = kIdentity;
    // Rotations about one axis are built directly (exact zeros and ones elsewhere).
    if (x == 0.0f && y == 0.0f && z != 0.0f) {
        if (z < 0.0f) s = -s;
        at(m, 0, 0) = c, at(m, 1, 1) = c, at(m, 0, 1) = -s, at(m, 1, 0) = s;
        return m;
    }
    if (x == 0.0f && z == 0.0f && y != 0.0f) {
        if (y < 0.0f) s = -s;
        at(m, 0, 0) = c, at(m, 2, 2) = c, at(m, 0, 2) = s, at(m, 2, 0) = -s;
        return m;
    }
    if (y == 0.0f && z == 0.0f && x != 0.0f) {
        if (x < 0.0f) s = -s;
        at(m, 1, 1) = c, at(m, 2, 2) = c, at(m, 1, 2) = -s, at(m, 2, 1) = s;
        return m;
    }
    const float length = std::sqrt(x * x + y * y + z * z);
    if (length <= 1.0e-4f) return std::nullopt;
    x /= length, y /= length, z /= length;
    const float xx = x * x, yy = y * y, zz = z * z, xy = x * y, yz = y * z, zx = z * x;
    const float xs = x * s, ys = y * s, zs = z * s, oneMinusC = 1.0f - c;
    at(m, 0, 0) = oneMinusC * xx + c, at(m, 0, 1) = oneMinusC * xy - zs, at(m, 0, 2) = oneMinusC * zx + ys;
    at(m, 1, 0) = oneMinusC * xy + zs, at(m, 1, 1) = oneMinusC * yy + c, at(m, 1, 2) = oneMinusC * yz - xs;
    at(m, 2, 0) = oneMinusC * zx - ys, at(m, 2, 1) = oneMinusC * yz + xs, at(m, 2, 2) = oneMinusC * zz + c;
    return m;
}

Matrix frustum(float left, float right, float bottom, float top, float nearVal, float farVal) {
    Matrix m{};
    at(m, 0, 0) = (2.0f * nearVal) / (right - left);
    at(m, 0, 2) = (right + left) / (right - left);
    at(m, 1, 1) = (2.0f * nearVal) / (top - bottom);
    at(m, 1, 2) = (top + bottom) / (top - bottom);
    at(m, 2, 2) = -(farVal + nearVal) / (farVal - nearVal);
    at(m, 2, 3) = -(2.0f * farVal * nearVal) / (farVal - nearVal);
    at(m, 3, 2) = -1.0f;
    return m;
}

Matrix ortho(float left, float right, float bottom, float top, float nearVal, float farVal) {
    Matrix m = kIdentity;
    at(m, 0, 0) = 2.0f / (right - left);
    at(m, 0, 3) = -(right + left) / (right - left);
    at(m, 1, 1) = 2.0f / (top - bottom);
    at(m, 1, 3) = -(top + bottom) / (top - bottom);
    at(m, 2, 2) = -2.0f / (farVal - nearVal);
    at(m, 2, 3) = -(farVal + nearVal) / (farVal - nearVal);
    return m;
}

glm::vec4 timesMatrix(const glm::vec4& v, const Matrix& m) {
    glm::vec4 u;
    for (int i = 0; i < 4; ++i) u[i] = v.x * m[4 * i] + v.y * m[4 * i + 1] + v.z * m[4 * i + 2] + v.w * m[4 * i + 3];
    return u;
}

}  // namespace mygl
