#include "matrix_inverse.h"

#include <cmath>
#include <utility>

namespace mygl {
namespace {

constexpr unsigned k3DFlags = kRotationFlag | kTranslationFlag | kUniformScaleFlag | kGeneralScaleFlag | kGeneral3DFlag;

// Whether no flag outside `allowed` is set.
bool onlyFlags(unsigned flags, unsigned allowed) { return (flags & ~allowed) == 0; }

float square(float x) { return x * x; }
float dot3(const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The translation column of an affine inverse: -(R^-1 t), each row summed left to right.
void invertTranslation(const Matrix& in, Matrix& out) {
    for (int row = 0; row < 3; ++row) {
        at(out, row, 3) =
            -(at(in, 0, 3) * at(out, row, 0) + at(in, 1, 3) * at(out, row, 1) + at(in, 2, 3) * at(out, row, 2));
    }
}

// A general affine matrix: the 3x3 adjugate over the determinant, whose six terms are summed
// as positive and negative parts (Graphics Gems II, as the reference).
bool invertAffine(const Matrix& in, Matrix& out) {
    auto m = [&](int r, int c) { return at(in, r, c); };
    float positive = 0.0f, negative = 0.0f;
    for (float t : {m(0, 0) * m(1, 1) * m(2, 2), m(1, 0) * m(2, 1) * m(0, 2), m(2, 0) * m(0, 1) * m(1, 2),
                    -m(2, 0) * m(1, 1) * m(0, 2), -m(1, 0) * m(0, 1) * m(2, 2), -m(0, 0) * m(2, 1) * m(1, 2)}) {
        (t >= 0.0f ? positive : negative) += t;
    }
    float det = positive + negative;
    if (std::fabs(det) < 1e-25f) return false;
    det = 1.0f / det;
    at(out, 0, 0) = (m(1, 1) * m(2, 2) - m(2, 1) * m(1, 2)) * det;
    at(out, 0, 1) = -(m(0, 1) * m(2, 2) - m(2, 1) * m(0, 2)) * det;
    at(out, 0, 2) = (m(0, 1) * m(1, 2) - m(1, 1) * m(0, 2)) * det;
    at(out, 1, 0) = -(m(1, 0) * m(2, 2) - m(2, 0) * m(1, 2)) * det;
    at(out, 1, 1) = (m(0, 0) * m(2, 2) - m(2, 0) * m(0, 2)) * det;
    at(out, 1, 2) = -(m(0, 0) * m(1, 2) - m(1, 0) * m(0, 2)) * det;
    at(out, 2, 0) = (m(1, 0) * m(2, 1) - m(2, 0) * m(1, 1)) * det;
    at(out, 2, 1) = -(m(0, 0) * m(2, 1) - m(2, 0) * m(0, 1)) * det;
    at(out, 2, 2) = (m(0, 0) * m(1, 1) - m(1, 0) * m(0, 1)) * det;
    invertTranslation(in, out);
    return true;
}

// Rotation, uniform scale and translation are undone part by part; anything else is general.
bool invert3D(const Matrix& in, Matrix& out, unsigned flags) {
    if (!onlyFlags(flags, kRotationFlag | kTranslationFlag | kUniformScaleFlag)) return invertAffine(in, out);
    if (flags & (kUniformScaleFlag | kRotationFlag)) {
        float scale = 1.0f;
        if (flags & kUniformScaleFlag) {
            scale = at(in, 0, 0) * at(in, 0, 0) + at(in, 0, 1) * at(in, 0, 1) + at(in, 0, 2) * at(in, 0, 2);
            if (scale == 0.0f) return false;
            scale = 1.0f / scale;
        }
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) at(out, r, c) = flags & kUniformScaleFlag ? scale * at(in, c, r) : at(in, c, r);
        }
    } else {  // translation only
        for (int r = 0; r < 3; ++r) at(out, r, 3) = -at(in, r, 3);
        return true;
    }
    if (flags & kTranslationFlag) invertTranslation(in, out);
    return true;
}

// Scales (and a translation) on the diagonal: `axes` 2 or 3.
bool invertDiagonal(const Matrix& in, Matrix& out, unsigned flags, int axes) {
    for (int i = 0; i < axes; ++i) {
        if (at(in, i, i) == 0.0f) return false;
    }
    for (int i = 0; i < axes; ++i) at(out, i, i) = 1.0f / at(in, i, i);
    if (flags & kTranslationFlag) {
        for (int i = 0; i < axes; ++i) at(out, i, 3) = -(at(in, i, 3) * at(out, i, i));
    }
    return true;
}

// Gauss-Jordan elimination with partial pivoting on [m | I], as the reference's general case.
bool invertGeneral(const Matrix& m, Matrix& out) {
    float rows[4][8];
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            rows[r][c] = at(m, r, c);
            rows[r][4 + c] = r == c ? 1.0f : 0.0f;
        }
    }
    float* p[4] = {rows[0], rows[1], rows[2], rows[3]};
    for (int col = 0; col < 3; ++col) {
        for (int r = 3; r > col; --r) {
            if (std::fabs(p[r][col]) > std::fabs(p[r - 1][col])) std::swap(p[r], p[r - 1]);
        }
        if (p[col][col] == 0.0f) return false;
        for (int r = col + 1; r < 4; ++r) {
            const float factor = p[r][col] / p[col][col];
            for (int c = col + 1; c < 8; ++c) {
                if (c >= 4 && p[col][c] == 0.0f) continue;
                p[r][c] -= factor * p[col][c];
            }
        }
    }
    if (p[3][3] == 0.0f) return false;
    for (int col = 3; col >= 0; --col) {  // back substitution
        const float s = 1.0f / p[col][col];
        for (int c = 4; c < 8; ++c) p[col][c] = col == 3 ? p[col][c] * s : s * p[col][c];
        for (int r = col - 1; r >= 0; --r) {
            const float factor = p[r][col];
            for (int c = 4; c < 8; ++c) p[r][c] -= p[col][c] * factor;
        }
    }
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) at(out, r, c) = p[r][4 + c];
    }
    return true;
}

}  // namespace

MatrixAnalysis analyseValues(const Matrix& m) {
    auto zero = [&](std::initializer_list<int> indices) {
        for (int i : indices) {
            if (m[static_cast<std::size_t>(i)] != 0.0f) return false;
        }
        return true;
    };
    unsigned flags = zero({12, 13, 14}) ? 0u : kTranslationFlag;
    const bool affineBottom = zero({3, 7, 11}) && m[15] == 1.0f;
    if (affineBottom && zero({1, 2, 4, 6, 8, 9}) && m[0] == 1.0f && m[5] == 1.0f && m[10] == 1.0f && flags == 0) {
        return {MatrixType::Identity, 0};
    }
    if (affineBottom && zero({1, 2, 4, 6, 8, 9, 14}) && m[10] == 1.0f) {
        if (m[0] != 1.0f || m[5] != 1.0f) flags |= kGeneralScaleFlag;
        return {MatrixType::NoRotation2D, flags};
    }
    if (affineBottom && zero({2, 6, 8, 9, 14}) && m[10] == 1.0f) {
        const float mm = m[0] * m[0] + m[1] * m[1], m4m4 = m[4] * m[4] + m[5] * m[5], mm4 = m[0] * m[4] + m[1] * m[5];
        if (square(mm - 1) > square(1e-6f) || square(m4m4 - 1) > square(1e-6f)) flags |= kGeneralScaleFlag;
        flags |= square(mm4) > square(1e-6f) ? kGeneral3DFlag : kRotationFlag;
        return {MatrixType::General2D, flags};
    }
    if (affineBottom && zero({1, 2, 4, 6, 8, 9})) {
        if (square(m[0] - m[5]) < square(1e-6f) && square(m[0] - m[10]) < square(1e-6f)) {
            if (square(m[0] - 1.0f) > square(1e-6f)) flags |= kUniformScaleFlag;
        } else {
            flags |= kGeneralScaleFlag;
        }
        return {MatrixType::NoRotation3D, flags};
    }
    if (affineBottom) {
        const float c1 = dot3(&m[0], &m[0]), c2 = dot3(&m[4], &m[4]), c3 = dot3(&m[8], &m[8]), d1 = dot3(&m[0], &m[4]);
        if (square(c1 - c2) < square(1e-6f) && square(c1 - c3) < square(1e-6f)) {
            if (square(c1 - 1.0f) > square(1e-6f)) flags |= kUniformScaleFlag;
        } else {
            flags |= kGeneralScaleFlag;
        }
        if (square(d1) < square(1e-6f)) {
            // The third column must be the cross product of the first two.
            const float cx = m[1] * m[6] - m[2] * m[5] - m[8], cy = m[2] * m[4] - m[0] * m[6] - m[9],
                        cz = m[0] * m[5] - m[1] * m[4] - m[10];
            flags |= cx * cx + cy * cy + cz * cz < square(1e-6f) ? kRotationFlag : kGeneral3DFlag;
        } else {
            flags |= kGeneral3DFlag;
        }
        return {MatrixType::General3D, flags};
    }
    if (zero({1, 2, 3, 4, 6, 7, 12, 13, 15}) && m[11] == -1.0f) return {MatrixType::Perspective, flags | kGeneralFlag};
    return {MatrixType::General, flags | kGeneralFlag};
}

MatrixType typeFromFlags(const Matrix& m, unsigned flags) {
    if (flags == 0) return MatrixType::Identity;
    if (onlyFlags(flags, kTranslationFlag | kUniformScaleFlag | kGeneralScaleFlag)) {
        return m[10] == 1.0f && m[14] == 0.0f ? MatrixType::NoRotation2D : MatrixType::NoRotation3D;
    }
    if (onlyFlags(flags, k3DFlags)) {
        const bool flat =
            m[8] == 0.0f && m[9] == 0.0f && m[2] == 0.0f && m[6] == 0.0f && m[10] == 1.0f && m[14] == 0.0f;
        return flat ? MatrixType::General2D : MatrixType::General3D;
    }
    const bool perspective = m[4] == 0.0f && m[12] == 0.0f && m[1] == 0.0f && m[13] == 0.0f && m[2] == 0.0f &&
                             m[6] == 0.0f && m[3] == 0.0f && m[7] == 0.0f && m[11] == -1.0f && m[15] == 0.0f;
    return perspective ? MatrixType::Perspective : MatrixType::General;
}

Matrix invert(const Matrix& m, MatrixType type, unsigned flags) {
    Matrix out = kIdentity;
    bool ok = true;
    switch (type) {
    case MatrixType::Identity: break;
    case MatrixType::NoRotation3D: ok = invertDiagonal(m, out, flags, 3); break;
    case MatrixType::NoRotation2D: ok = invertDiagonal(m, out, flags, 2); break;
    case MatrixType::General2D:
    case MatrixType::General3D: ok = invert3D(m, out, flags); break;
    case MatrixType::General:
    case MatrixType::Perspective: ok = invertGeneral(m, out); break;
    }
    return ok ? out : kIdentity;
}

}  // namespace mygl
