#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <immintrin.h>

#include "glrenderer/round_to_even.h"
#include "window_vertex.h"

namespace glrenderer {

// Sub-pixel precision of the reference (GL_SUBPIXEL_BITS = 8).
inline constexpr int kSubpixelBits = 8;
inline constexpr float kSubpixelScale = 256.0f;

// A position snapped to 1/256 pixel with pixel centers on whole numbers, computed as the
// reference computes it: float((v - 0.5) * 256) rounded to nearest, ties to even.
struct FixedPoint {
    std::int64_t x, y;
};

inline std::int64_t snapToFixed(float windowCoordinate) {
    return roundToEven((windowCoordinate - 0.5f) * kSubpixelScale);
}

inline FixedPoint snap(const WindowVertex& v) { return {snapToFixed(v.x), snapToFixed(v.y)}; }

// Window coordinates beyond this are only reachable through degenerate w; triangles with such a
// vertex are dropped rather than fed to the fixed-point conversion.
inline constexpr float kMaxWindowCoordinate = 1 << 24;

// |x| and |y| below kMaxWindowCoordinate, z, 1 / w and the colour finite, in two comparisons of
// four lanes (NaN fails every one): all four lanes set when the vertex can be set up.
static_assert(offsetof(WindowVertex, invW) == 12 && offsetof(WindowVertex, color) == 16);
inline __m128 usableLanes(const WindowVertex& v) {
    const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
    const __m128 infinity = _mm_set1_ps(std::numeric_limits<float>::infinity());
    const __m128 limits = _mm_setr_ps(kMaxWindowCoordinate, kMaxWindowCoordinate,
                                      std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity());
    return _mm_and_ps(_mm_cmplt_ps(_mm_and_ps(_mm_loadu_ps(&v.x), magnitude), limits),
                      _mm_cmplt_ps(_mm_and_ps(_mm_loadu_ps(&v.color.x), magnitude), infinity));
}

// A window vertex's snapped position and whether it can be set up (usableLanes), computed once
// per vertex by the vertex stage: a strip or an indexed mesh shares a vertex among several
// triangles. `fixed` is meaningful only when `usable`.
struct SnappedVertex {
    FixedPoint fixed;
    bool usable;
};
inline SnappedVertex snapVertex(const WindowVertex& v) { return {snap(v), _mm_movemask_ps(usableLanes(v)) == 0xF}; }

// Twice the signed area of the snapped triangle in internal (y-down) coordinates. Negative means
// counter-clockwise as seen in GL window coordinates (y up).
inline std::int64_t fixedArea(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

enum class Facing { Front, Back, ZeroArea };

inline Facing facingOf(std::int64_t area, bool frontFaceCCW) {
    if (area == 0) return Facing::ZeroArea;
    const bool counterClockwise = area < 0;
    return counterClockwise == frontFaceCCW ? Facing::Front : Facing::Back;
}

// The facing the reference's draw module gives a triangle that goes through it (a draw with a
// vertex to clip, or an unfilled polygon mode), before and besides setup's (draw_pipe_cull.c):
// the float determinant of the window positions in the order the triangle reaches the stage,
// with e = v0 - v2 and f = v1 - v2. Negative is counter-clockwise in GL's window; zero area
// counts as back-facing.
inline float drawModuleDeterminant(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2) {
    const float ex = v0.x - v2.x, ey = v0.y - v2.y;
    const float fx = v1.x - v2.x, fy = v1.y - v2.y;
    return ex * fy - ey * fx;
}

inline Facing drawModuleFacing(float determinant, bool frontFaceCCW) {
    return determinant != 0.0f && (determinant < 0.0f) == frontFaceCCW ? Facing::Front : Facing::Back;
}

// The draw module's two-sided stage: a triangle back-facing by its determinant, not 0, takes the
// back colours.
inline bool drawModuleFacesBack(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                                bool frontFaceCCW) {
    const float determinant = drawModuleDeterminant(v0, v1, v2);
    return determinant != 0.0f && drawModuleFacing(determinant, frontFaceCCW) == Facing::Back;
}

// A linear function of the pixel position, a(x, y) = a0 + dadx * x + dady * y, evaluated at the
// pixel's integer coordinates (a0 already holds the half-pixel offset) with the reference's fma.
struct AttributePlane {
    float a0 = 0, dadx = 0, dady = 0;
    float at(float x, float y) const { return std::fma(dady, y, std::fma(dadx, x, a0)); }
};

// N planes side by side, plane i in element i of each array: FourPlanes stores its lanes into
// them as they are (into AttributePlanes it transposes them).
template <int N>
struct AttributePlanes {
    float a0[N] = {}, dadx[N] = {}, dady[N] = {};

    AttributePlane operator[](int i) const { return {a0[i], dadx[i], dady[i]}; }
    void set(int i, const AttributePlane& p) { a0[i] = p.a0, dadx[i] = p.dadx, dady[i] = p.dady; }
};

// Four planes at once, lane i of each vector for plane i (a0, dadx, dady as AttributePlane's).
struct FourPlanes {
    __m128 a0, dadx, dady;

    void store(AttributePlanes<4>& out) const {
        _mm_storeu_ps(out.a0, a0);
        _mm_storeu_ps(out.dadx, dadx);
        _mm_storeu_ps(out.dady, dady);
    }
    // The planes of the first two lanes.
    void store(AttributePlanes<2>& out) const {
        _mm_storel_pi(reinterpret_cast<__m64*>(out.a0), a0);
        _mm_storel_pi(reinterpret_cast<__m64*>(out.dadx), dadx);
        _mm_storel_pi(reinterpret_cast<__m64*>(out.dady), dady);
    }

    // Planes `first` .. `first + count - 1` (count <= 4) to consecutive AttributePlanes, writing
    // nothing past the last one.
    void store(AttributePlane* out, int first, int count) const {
        __m128 rows[4] = {a0, dadx, dady, _mm_setzero_ps()};  // to (a0, dadx, dady, 0) per plane
        _MM_TRANSPOSE4_PS(rows[0], rows[1], rows[2], rows[3]);
        float* to = &out->a0;
        for (int i = 0; i < count - 1; ++i, to += 3) _mm_storeu_ps(to, rows[first + i]);
        _mm_storel_pi(reinterpret_cast<__m64*>(to), rows[first + count - 1]);
        _mm_store_ss(to + 2, _mm_movehl_ps(rows[first + count - 1], rows[first + count - 1]));
    }
};

// Builds planes through three vertices from their unsnapped window positions, with the
// reference's order of float operations (the planes are anchored at v0).
class PlaneBuilder {
public:
    PlaneBuilder(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2) {
        const float dx01 = v0.x - v1.x, dy01 = v0.y - v1.y, dx20 = v2.x - v0.x, dy20 = v2.y - v0.y;
        const float oneOverArea = 1.0f / (dx01 * dy20 - dy01 * dx20);
        dy20Scaled_ = dy20 * oneOverArea, dy01Scaled_ = dy01 * oneOverArea;
        dx01Scaled_ = dx01 * oneOverArea, dx20Scaled_ = dx20 * oneOverArea;
        x0Center_ = v0.x - 0.5f, y0Center_ = v0.y - 0.5f;
    }

    AttributePlane plane(float a0, float a1, float a2) const {
        const float da01 = a0 - a1;
        const float da20 = a2 - a0;
        AttributePlane p;
        p.dadx = da01 * dy20Scaled_ - da20 * dy01Scaled_;
        p.dady = da20 * dx01Scaled_ - da01 * dx20Scaled_;
        p.a0 = a0 - (p.dadx * x0Center_ + p.dady * y0Center_);
        return p;
    }
    // plane() of each lane: the same operations, so the same bits.
    FourPlanes planes(__m128 a0, __m128 a1, __m128 a2) const {
        const __m128 da01 = _mm_sub_ps(a0, a1);
        const __m128 da20 = _mm_sub_ps(a2, a0);
        FourPlanes p;
        p.dadx = _mm_sub_ps(_mm_mul_ps(da01, _mm_set1_ps(dy20Scaled_)), _mm_mul_ps(da20, _mm_set1_ps(dy01Scaled_)));
        p.dady = _mm_sub_ps(_mm_mul_ps(da20, _mm_set1_ps(dx01Scaled_)), _mm_mul_ps(da01, _mm_set1_ps(dx20Scaled_)));
        p.a0 = _mm_sub_ps(
            a0, _mm_add_ps(_mm_mul_ps(p.dadx, _mm_set1_ps(x0Center_)), _mm_mul_ps(p.dady, _mm_set1_ps(y0Center_))));
        return p;
    }

private:
    // The edge deltas times 1 / area, as the reference scales them before the attributes' deltas.
    float dy20Scaled_, dy01Scaled_, dx01Scaled_, dx20Scaled_;
    float x0Center_, y0Center_;
};

// Planes of attributes that are the same at every pixel (a point's, a bitmap's).
struct ConstantPlanes {
    AttributePlane plane(float a) const { return {a, 0.0f, 0.0f}; }
};

}  // namespace glrenderer
