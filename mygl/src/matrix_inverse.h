#pragma once
// Matrix types and inverses as the reference computes them (Mesa's math/m_matrix.c): the type
// picks the inversion, and each inversion rounds in its own order, in float.
#include "matrix_math.h"

namespace mygl {

// Mesa's matrix flags: what operations have applied, or what an analysis of the values found
// after a load or a general product.
enum MatrixFlag : unsigned {
    kGeneralFlag = 1,
    kRotationFlag = 2,
    kTranslationFlag = 4,
    kUniformScaleFlag = 8,
    kGeneralScaleFlag = 16,
    kGeneral3DFlag = 32,
    kPerspectiveFlag = 64,
};

enum class MatrixType { General, Identity, NoRotation3D, Perspective, General2D, NoRotation2D, General3D };

// The type and flags that an analysis of the values finds.
struct MatrixAnalysis {
    MatrixType type;
    unsigned flags;
};
MatrixAnalysis analyseValues(const Matrix& m);
// The type of a matrix whose flags are known.
MatrixType typeFromFlags(const Matrix& m, unsigned flags);

// The inverse; the identity for a matrix the reference finds singular.
Matrix invert(const Matrix& m, MatrixType type, unsigned flags);

}  // namespace mygl
