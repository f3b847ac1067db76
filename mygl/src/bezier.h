#pragma once
// Bezier curves and tensor-product surfaces in the reference's float arithmetic (Mesa's
// math/m_eval.c, measured identical through glEvalCoord): Horner's scheme for points, de
// Casteljau's for a surface point with its partial derivatives (GL_AUTO_NORMAL).

namespace mygl {

// The point at t of the curve of `order` control points of `dim` components, point i at
// points[i * stride]; into out[0..dim).
void bezierCurve(const float* points, int stride, float* out, float t, int dim, int order);

// The point at (u, v) of the surface of uorder x vorder control points, point (i, j) at
// net[(i * vorder + j) * dim].
void bezierSurface(const float* net, float* out, float u, float v, int dim, int uorder, int vorder);

// The same point by de Casteljau's algorithm, with the directions of the partial derivatives in
// u and v (their lengths are not scaled).
void bezierSurfaceWithDerivatives(const float* net, float* out, float* du, float* dv, float u, float v, int dim,
                                  int uorder, int vorder);

}  // namespace mygl
