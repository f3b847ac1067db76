#pragma once
// 4x4 matrices in double, column-major as GL stores them, for gluProject and gluUnProject.

namespace mygl::glu {

// out = a * b. out may not alias a or b.
void multiply(const double a[16], const double b[16], double out[16]);
// out = m * v.
void transform(const double m[16], const double v[4], double out[4]);
// false (out unspecified) when m is singular.
bool invert(const double m[16], double out[16]);

}  // namespace mygl::glu
