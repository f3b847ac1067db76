#pragma once
// A matrix of a matrix stack together with what the reference knows about its kind. Mesa
// tracks whether a matrix may be projective; products with a matrix it believes affine skip
// the bottom row (taken as 0 0 0 1), and glTranslate/glScale change the matrix in place. For
// finite values that gives the same numbers as full products, but not where Inf or NaN meet
// the zeros of the bottom row: there the reference stays finite and so must we.
#include <optional>

#include "matrix_inverse.h"
#include "matrix_math.h"

namespace mygl {

class StackMatrix {
public:
    const Matrix& matrix() const { return m_; }
    // Whether products with this matrix take the full 4x4 path.
    bool mayBeProjective() const { return projective_; }

    // Each returns false when the reference treats the call as no change at all (then it does
    // not even end its vertex batch).
    bool load(const Matrix& m);
    bool multiply(const Matrix& m);
    void loadIdentity();
    void translate(float x, float y, float z);
    void scale(float x, float y, float z);
    void rotate(float angleDegrees, float x, float y, float z);
    void frustum(float left, float right, float bottom, float top, float nearVal, float farVal);
    void ortho(float left, float right, float bottom, float top, float nearVal, float farVal);

    // The reference re-derives the kind from the values when it validates state (at a draw,
    // a glPushMatrix, a glReadPixels), if a load or a general product made it unknown.
    void settleKind();

    // What lighting needs (after settleKind()): whether the reference knows the matrix to keep
    // lengths (only rotations and translations were applied: its flags say so), and the inverse
    // as the reference computes it, by a method chosen from the matrix type.
    bool lengthPreserving() const;
    Matrix inverse() const;

private:
    void multiplyKnown(const Matrix& m, bool projective, unsigned flags);
    // An operation that applied `flags`: the type is then derived from the flags.
    void applied(unsigned flags) {
        flags_ |= flags;
        typeKnown_ = false;
    }

    Matrix m_ = kIdentity;
    bool projective_ = false;
    bool kindUnknown_ = false;
    unsigned flags_ = 0;
    // The type (which inversion applies) when known apart from the flags: glLoadIdentity makes
    // it the identity and keeps the flags; an analysis of the values sets both.
    MatrixType type_ = MatrixType::Identity;
    bool typeKnown_ = true;
};

// projection * modelview, as the reference forms the matrix its vertex stage uses.
Matrix combine(const StackMatrix& projection, const StackMatrix& modelview);

}  // namespace mygl
