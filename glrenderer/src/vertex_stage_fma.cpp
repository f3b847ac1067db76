// The vertex stage for CPUs with FMA, compiled with -mfma (and so AVX) -msse4.1 and called only
// after cpuHasFma(). Each lane performs ColumnTransform's, clipOutcode's and ViewportTransform::apply's
// float operations in the same order, so the bits match theirs.
#include <immintrin.h>

#include <algorithm>
#include <array>

#include "vertex_stage.h"

namespace glrenderer {
namespace {

// clipOutcode's plane bits from the lanes (x, y, z) of w - p (index bits 0-2) and of p + w
// (bits 3-5) that are outside (not >= 0, so NaN is outside): planes 0, 2, 5 are w - x, w - y,
// w - z; 1, 3, 4 are x + w, y + w, z + w. A table: the bits moved one by one were a sixth of the
// stage's instructions.
constexpr std::array<Outcode, 64> kOutcodeOfLanes = [] {
    std::array<Outcode, 64> outcodes{};
    for (int lanes = 0; lanes < 64; ++lanes) {
        const int minus = lanes & 7, plus = lanes >> 3;
        outcodes[static_cast<std::size_t>(lanes)] = static_cast<Outcode>(
            (minus & 1) | (minus & 2) << 1 | (minus & 4) << 3 | (plus & 1) << 1 | (plus & 2) << 2 | (plus & 4) << 2);
    }
    return outcodes;
}();

// A vertex's outcode from the masks of the lanes of w - p and p + w that are inside, its lanes
// from bit `first` (0 or 4: the half of a 256-bit register it is in).
Outcode outcodeOf(int insideMinus, int insidePlus, int first) {
    const int inside = (insideMinus >> first & 7) | (insidePlus >> first & 7) << 3;
    return kOutcodeOfLanes[static_cast<std::size_t>(~inside & 63)];
}

}  // namespace

// Two vertices a step, one in each 128-bit half (AVX, which every FMA CPU has): the same
// operations on each as on one in four lanes (half the instructions a vertex). An odd count's
// last vertex is staged in both halves, its second results written over its first.
StagedSummary stageVerticesFma(std::span<const Vertex> vertices, const Matrix& modelviewProjection,
                               const ViewportTransform& viewport, const StagedVertices& out) {
    const auto column = [&](int k) {
        return _mm256_broadcast_ps(reinterpret_cast<const __m128*>(&modelviewProjection[4 * k]));
    };
    const __m256 c0 = column(0), c1 = column(1), c2 = column(2), c3 = column(3);
    const __m256 scale = _mm256_setr_ps(viewport.scaleX(), viewport.scaleY(), viewport.scaleZ(), 0.0f,
                                        viewport.scaleX(), viewport.scaleY(), viewport.scaleZ(), 0.0f);
    const __m256 translate = _mm256_setr_ps(viewport.translateX(), viewport.translateY(), viewport.translateZ(), 0.0f,
                                            viewport.translateX(), viewport.translateY(), viewport.translateZ(), 0.0f);
    const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
    // (The arrays in locals: stored through, they could be `out` itself, read again each time.)
    glm::vec4* const clipPositions = out.clipPositions;
    Outcode* const outcodes = out.outcodes;
    WindowVertex* const windowVertices = out.windowVertices;
    Outcode anyOutside = 0;
    __m256 colorsOne = _mm256_castsi256_ps(_mm256_set1_epi32(-1));  // the lanes of colours equal to 1 so far
    for (std::size_t i = 0; i < vertices.size(); i += 2) {
        const std::size_t j = std::min(i + 1, vertices.size() - 1);
        if (i + kVertexFetchAhead + 1 < vertices.size()) {
            __builtin_prefetch(&vertices[i + kVertexFetchAhead]);
            __builtin_prefetch(&vertices[i + kVertexFetchAhead + 1]);
        }
        const __m256 v = _mm256_loadu2_m128(&vertices[j].position.x, &vertices[i].position.x);
        // ColumnTransform::apply's products and sums, in its order.
        __m256 p =
            _mm256_add_ps(_mm256_mul_ps(c0, _mm256_permute_ps(v, 0x00)), _mm256_mul_ps(c1, _mm256_permute_ps(v, 0x55)));
        p = _mm256_add_ps(p, _mm256_mul_ps(c2, _mm256_permute_ps(v, 0xAA)));
        p = _mm256_add_ps(p, _mm256_mul_ps(c3, _mm256_permute_ps(v, 0xFF)));
        _mm256_storeu2_m128(&clipPositions[j].x, &clipPositions[i].x, p);
        const __m256 w = _mm256_permute_ps(p, 0xFF);
        // Not >= 0 (ordered: NaN is outside) is outside.
        const int insideMinus = _mm256_movemask_ps(_mm256_cmp_ps(_mm256_sub_ps(w, p), zero, _CMP_GE_OS));
        const int insidePlus = _mm256_movemask_ps(_mm256_cmp_ps(_mm256_add_ps(p, w), zero, _CMP_GE_OS));
        const Outcode first = outcodeOf(insideMinus, insidePlus, 0), second = outcodeOf(insideMinus, insidePlus, 4);
        outcodes[i] = first;
        outcodes[j] = second;
        anyOutside |= first | second;

        const __m256 invW = _mm256_div_ps(one, w);
        const __m256 window = _mm256_fmadd_ps(_mm256_mul_ps(p, invW), scale, translate);
        const __m256 xyzInvW = _mm256_blend_ps(window, invW, 0b10001000);
        const __m256 colors = _mm256_loadu2_m128(&vertices[j].color.x, &vertices[i].color.x);
        colorsOne = _mm256_and_ps(colorsOne, _mm256_cmp_ps(colors, one, _CMP_EQ_OQ));
        _mm256_storeu2_m128(&windowVertices[j].color.x, &windowVertices[i].color.x, colors);
        windowVertices[i].fogCoord = windowVertices[j].fogCoord = 0.0f;  // (set after the pass when fog is on)
        _mm256_storeu2_m128(&windowVertices[j].x, &windowVertices[i].x, xyzInvW);  // x, y, z, invW
    }
    constexpr int kAlphaLanes = 0b10001000;
    return {anyOutside, (_mm256_movemask_ps(colorsOne) & kAlphaLanes) == kAlphaLanes};
}

}  // namespace glrenderer
