#include "stack_matrix.h"

#include <cmath>
#include <cstring>

namespace mygl {
namespace {

bool hasAffineBottomRow(const Matrix& m) {
    return at(m, 3, 0) == 0.0f && at(m, 3, 1) == 0.0f && at(m, 3, 2) == 0.0f && at(m, 3, 3) == 1.0f;
}

}  // namespace

bool StackMatrix::load(const Matrix& m) {
    if (std::memcmp(m.data(), m_.data(), sizeof m_) == 0) return false;
    m_ = m;
    projective_ = true;
    kindUnknown_ = true;
    flags_ = kGeneralFlag;
    typeKnown_ = false;
    return true;
}

bool StackMatrix::multiply(const Matrix& m) {
    if (m == kIdentity) return false;
    m_ = mygl::multiply(m_, m);
    projective_ = true;
    kindUnknown_ = true;
    applied(kGeneralFlag);
    return true;
}

void StackMatrix::loadIdentity() {
    // The reference keeps the kind it had: only the values and the pending analysis change.
    m_ = kIdentity;
    kindUnknown_ = false;
    type_ = MatrixType::Identity;
    typeKnown_ = true;
}

void StackMatrix::translate(float x, float y, float z) {
    for (int row = 0; row < 4; ++row) {
        at(m_, row, 3) = at(m_, row, 0) * x + at(m_, row, 1) * y + at(m_, row, 2) * z + at(m_, row, 3);
    }
    applied(kTranslationFlag);
}

void StackMatrix::scale(float x, float y, float z) {
    for (int row = 0; row < 4; ++row) {
        at(m_, row, 0) *= x;
        at(m_, row, 1) *= y;
        at(m_, row, 2) *= z;
    }
    applied(std::fabs(x - y) < 1e-8f && std::fabs(x - z) < 1e-8f ? kUniformScaleFlag : kGeneralScaleFlag);
}

void StackMatrix::rotate(float angleDegrees, float x, float y, float z) {
    if (const std::optional<Matrix> r = rotation(angleDegrees, x, y, z)) multiplyKnown(*r, false, kRotationFlag);
}

void StackMatrix::frustum(float left, float right, float bottom, float top, float nearVal, float farVal) {
    multiplyKnown(mygl::frustum(left, right, bottom, top, nearVal, farVal), true, kPerspectiveFlag);
}

void StackMatrix::ortho(float left, float right, float bottom, float top, float nearVal, float farVal) {
    multiplyKnown(mygl::ortho(left, right, bottom, top, nearVal, farVal), false, kGeneralScaleFlag | kTranslationFlag);
}

void StackMatrix::settleKind() {
    if (!kindUnknown_) return;
    projective_ = !hasAffineBottomRow(m_);
    kindUnknown_ = false;
    const MatrixAnalysis analysis = analyseValues(m_);
    flags_ = analysis.flags;
    type_ = analysis.type;
    typeKnown_ = true;
}

bool StackMatrix::lengthPreserving() const { return (flags_ & ~(kRotationFlag | kTranslationFlag)) == 0; }

Matrix StackMatrix::inverse() const { return invert(m_, typeKnown_ ? type_ : typeFromFlags(m_, flags_), flags_); }

void StackMatrix::multiplyKnown(const Matrix& m, bool projective, unsigned flags) {
    applied(flags);
    projective_ = projective_ || projective;
    m_ = projective_ ? mygl::multiply(m_, m) : multiplyAffine(m_, m);
}

Matrix combine(const StackMatrix& projection, const StackMatrix& modelview) {
    const bool projective = projection.mayBeProjective() || modelview.mayBeProjective();
    return projective ? multiply(projection.matrix(), modelview.matrix())
                      : multiplyAffine(projection.matrix(), modelview.matrix());
}

}  // namespace mygl
