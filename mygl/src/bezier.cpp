#include "bezier.h"

#include <array>

namespace mygl {
namespace {

constexpr int kMaxOrder = 30;  // GL_MAX_EVAL_ORDER

// The reference multiplies by a tabulated float 1/i where the binomial coefficient needs a
// division by i.
float reciprocal(int i) { return 1.0f / static_cast<float>(i); }

}  // namespace

// Horner's scheme: ((C(n,0) s b0 + C(n,1) t b1) s + C(n,2) t^2 b2) s + ..., s = 1 - t, the
// binomial coefficients built up as C(n,i) = C(n,i-1) * (n-i+1) * (1/i).
void bezierCurve(const float* points, int stride, float* out, float t, int dim, int order) {
    if (order < 2) {
        for (int k = 0; k < dim; ++k) out[k] = points[k];
        return;
    }
    const float s = 1.0f - t;
    float binomial = static_cast<float>(order - 1);
    for (int k = 0; k < dim; ++k) out[k] = s * points[k] + binomial * t * points[stride + k];
    float powerOfT = t * t;
    for (int i = 2; i < order; ++i) {
        binomial *= static_cast<float>(order - i);
        binomial *= reciprocal(i);
        const float* point = points + i * stride;
        for (int k = 0; k < dim; ++k) out[k] = s * out[k] + binomial * powerOfT * point[k];
        powerOfT *= t;
    }
}

// A curve through the net in the direction of the higher order first: the control polygon of
// the surface curve at the other parameter, then the point on it.
void bezierSurface(const float* net, float* out, float u, float v, int dim, int uorder, int vorder) {
    std::array<float, kMaxOrder * 4> polygon{};
    const int uStride = vorder * dim;  // from point (i, j) to (i + 1, j)
    if (vorder > uorder) {
        if (uorder < 2) return bezierCurve(net, dim, out, v, dim, vorder);
        for (int j = 0; j < vorder; ++j) bezierCurve(net + j * dim, uStride, &polygon[j * dim], u, dim, uorder);
        return bezierCurve(polygon.data(), dim, out, v, dim, vorder);
    }
    if (vorder < 2) return bezierCurve(net, dim, out, u, dim, uorder);
    for (int i = 0; i < uorder; ++i) bezierCurve(net + i * uStride, dim, &polygon[i * dim], v, dim, vorder);
    bezierCurve(polygon.data(), dim, out, u, dim, uorder);
}

namespace {

// de Casteljau on one component of the net: its values c(i, j) and a work grid d(i, j).
class Casteljau {
public:
    Casteljau(const float* net, int k, int dim, int uorder, int vorder, float u, float v)
        : net_(net), k_(k), dim_(dim), vorder_(vorder), uorder_(uorder), u_(u), v_(v), us_(1.0f - u), vs_(1.0f - v) {}

    // A control point's component. Past the net (an order of 1, where the reference reads
    // whatever memory follows its points) it is 0.
    float c(int i, int j) const { return i < uorder_ && j < vorder_ ? net_[(i * vorder_ + j) * dim_ + k_] : 0.0f; }
    float& d(int i, int j) { return work_[static_cast<std::size_t>(i * vorder_ + j)]; }

    // A step in u (between rows i and i + 1) and in v (between columns j and j + 1).
    float inU(float a, float b) const { return us_ * a + u_ * b; }
    float inV(float a, float b) const { return vs_ * a + v_ * b; }

    // Both orders 2, or the lower order below 3: the cases the reference writes out.
    void lowOrder(float& point, float& du, float& dv);
    // Both orders 3 or more.
    void highOrder(float& point, float& du, float& dv);

private:
    // The first bilinear steps, down to the second last (rows and columns 0..1 left).
    void bilinearSteps(int minOrder);

    const float* net_;
    int k_, dim_, vorder_, uorder_;
    float u_, v_, us_, vs_;
    std::array<float, kMaxOrder * kMaxOrder> work_{};
};

void Casteljau::lowOrder(float& point, float& du, float& dv) {
    if (uorder_ == vorder_) {  // both 2
        du = vs_ * (c(1, 0) - c(0, 0)) + v_ * (c(1, 1) - c(0, 1));
        dv = us_ * (c(0, 1) - c(0, 0)) + u_ * (c(1, 1) - c(1, 0));
        point = us_ * inV(c(0, 0), c(0, 1)) + u_ * inV(c(1, 0), c(1, 1));
        return;
    }
    if (uorder_ < vorder_) {  // uorder 2: row 1 carries the u differences, row 0 the point
        d(1, 0) = c(1, 0) - c(0, 0);
        d(0, 0) = inU(c(0, 0), c(1, 0));
        for (int j = 0; j < vorder_ - 1; ++j) {
            d(1, j + 1) = c(1, j + 1) - c(0, j + 1);
            d(1, j) = inV(d(1, j), d(1, j + 1));
            d(0, j + 1) = inU(c(0, j + 1), c(1, j + 1));
            d(0, j) = inV(d(0, j), d(0, j + 1));
        }
        for (int h = uorder_; h < vorder_ - 1; ++h) {
            for (int j = 0; j < vorder_ - h; ++j) {
                d(1, j) = inV(d(1, j), d(1, j + 1));
                d(0, j) = inV(d(0, j), d(0, j + 1));
            }
        }
        dv = d(0, 1) - d(0, 0);
        du = inV(d(1, 0), d(1, 1));
        point = inV(d(0, 0), d(0, 1));
        return;
    }
    // vorder 2: column 1 carries the v differences, column 0 the point
    d(0, 1) = c(0, 1) - c(0, 0);
    d(0, 0) = inV(c(0, 0), c(0, 1));
    for (int i = 0; i < uorder_ - 1; ++i) {
        d(i + 1, 1) = c(i + 1, 1) - c(i + 1, 0);
        d(i, 1) = inU(d(i, 1), d(i + 1, 1));
        d(i + 1, 0) = inV(c(i + 1, 0), c(i + 1, 1));
        d(i, 0) = inU(d(i, 0), d(i + 1, 0));
    }
    for (int h = vorder_; h < uorder_ - 1; ++h) {
        for (int i = 0; i < uorder_ - h; ++i) {
            d(i, 1) = inU(d(i, 1), d(i + 1, 1));
            d(i, 0) = inU(d(i, 0), d(i + 1, 0));
        }
    }
    du = d(1, 0) - d(0, 0);
    dv = inU(d(0, 1), d(1, 1));
    point = inU(d(0, 0), d(1, 0));
}

void Casteljau::bilinearSteps(int minOrder) {
    for (int i = 0; i < uorder_ - 1; ++i) {
        d(i, 0) = inU(c(i, 0), c(i + 1, 0));
        for (int j = 0; j < vorder_ - 1; ++j) {
            d(i, j + 1) = inU(c(i, j + 1), c(i + 1, j + 1));
            d(i, j) = inV(d(i, j), d(i, j + 1));
        }
    }
    for (int h = 2; h < minOrder - 1; ++h) {
        for (int i = 0; i < uorder_ - h; ++i) {
            d(i, 0) = inU(d(i, 0), d(i + 1, 0));
            for (int j = 0; j < vorder_ - h; ++j) {
                d(i, j + 1) = inU(d(i, j + 1), d(i + 1, j + 1));
                d(i, j) = inV(d(i, j), d(i, j + 1));
            }
        }
    }
}

void Casteljau::highOrder(float& point, float& du, float& dv) {
    const int minOrder = uorder_ < vorder_ ? uorder_ : vorder_;
    bilinearSteps(minOrder);
    if (uorder_ == vorder_) {
        du = vs_ * (d(1, 0) - d(0, 0)) + v_ * (d(1, 1) - d(0, 1));
        dv = us_ * (d(0, 1) - d(0, 0)) + u_ * (d(1, 1) - d(1, 0));
        point = us_ * inV(d(0, 0), d(0, 1)) + u_ * inV(d(1, 0), d(1, 1));
        return;
    }
    if (minOrder == uorder_) {  // rows 0 and 1 left: row 2 takes the u differences
        d(2, 0) = d(1, 0) - d(0, 0);
        d(0, 0) = inU(d(0, 0), d(1, 0));
        for (int j = 0; j < vorder_ - 1; ++j) {
            d(2, j + 1) = d(1, j + 1) - d(0, j + 1);
            d(2, j) = inV(d(2, j), d(2, j + 1));
            d(0, j + 1) = inU(d(0, j + 1), d(1, j + 1));
            d(0, j) = inV(d(0, j), d(0, j + 1));
        }
        for (int h = minOrder; h < vorder_ - 1; ++h) {
            for (int j = 0; j < vorder_ - h; ++j) {
                d(2, j) = inV(d(2, j), d(2, j + 1));
                d(0, j) = inV(d(0, j), d(0, j + 1));
            }
        }
        dv = d(0, 1) - d(0, 0);
        du = inV(d(2, 0), d(2, 1));
        point = inV(d(0, 0), d(0, 1));
        return;
    }
    // columns 0 and 1 left: column 2 takes the v differences
    d(0, 2) = d(0, 1) - d(0, 0);
    d(0, 0) = inV(d(0, 0), d(0, 1));
    for (int i = 0; i < uorder_ - 1; ++i) {
        d(i + 1, 2) = d(i + 1, 1) - d(i + 1, 0);
        d(i, 2) = inU(d(i, 2), d(i + 1, 2));
        d(i + 1, 0) = inV(d(i + 1, 0), d(i + 1, 1));
        d(i, 0) = inU(d(i, 0), d(i + 1, 0));
    }
    for (int h = minOrder; h < uorder_ - 1; ++h) {
        for (int i = 0; i < uorder_ - h; ++i) {
            d(i, 2) = inU(d(i, 2), d(i + 1, 2));
            d(i, 0) = inU(d(i, 0), d(i + 1, 0));
        }
    }
    du = d(1, 0) - d(0, 0);
    dv = inU(d(0, 2), d(1, 2));
    point = inU(d(0, 0), d(1, 0));
}

}  // namespace

void bezierSurfaceWithDerivatives(const float* net, float* out, float* du, float* dv, float u, float v, int dim,
                                  int uorder, int vorder) {
    const int minOrder = uorder < vorder ? uorder : vorder;
    for (int k = 0; k < dim; ++k) {
        Casteljau casteljau(net, k, dim, uorder, vorder, u, v);
        if (minOrder < 3)
            casteljau.lowOrder(out[k], du[k], dv[k]);
        else
            casteljau.highOrder(out[k], du[k], dv[k]);
    }
}

}  // namespace mygl
