// The vertex stage for CPUs with FMA, compiled with -mfma -msse4.1 and called only after
// cpuHasFma(). Each lane performs ColumnTransform's, clipOutcode's and ViewportTransform::apply's
// float operations in the same order, so the bits match theirs.
#include <immintrin.h>

#include <array>

#include "column_transform.h"
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

}  // namespace

Outcode stageVerticesFma(std::span<const Vertex> vertices, const Matrix& modelviewProjection,
                         const ViewportTransform& viewport, const StagedVertices& out) {
    const ColumnTransform toClip(modelviewProjection);
    const __m128 scale = _mm_setr_ps(viewport.scaleX(), viewport.scaleY(), viewport.scaleZ(), 0.0f);
    const __m128 translate = _mm_setr_ps(viewport.translateX(), viewport.translateY(), viewport.translateZ(), 0.0f);
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    Outcode anyOutside = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (i + kVertexFetchAhead < vertices.size()) __builtin_prefetch(&vertices[i + kVertexFetchAhead]);
        const __m128 p = toClip.apply(vertices[i].position);
        _mm_storeu_ps(&out.clipPositions[i].x, p);
        const __m128 w = _mm_shuffle_ps(p, p, _MM_SHUFFLE(3, 3, 3, 3));
        const int insideMinus = _mm_movemask_ps(_mm_cmpge_ps(_mm_sub_ps(w, p), zero));
        const int insidePlus = _mm_movemask_ps(_mm_cmpge_ps(_mm_add_ps(p, w), zero));
        const Outcode outcode =
            kOutcodeOfLanes[static_cast<std::size_t>(~((insideMinus & 7) | (insidePlus & 7) << 3) & 63)];
        out.outcodes[i] = outcode;
        anyOutside |= outcode;

        const __m128 invW = _mm_div_ps(one, w);
        const __m128 window = _mm_fmadd_ps(_mm_mul_ps(p, invW), scale, translate);
        WindowVertex& windowVertex = out.windowVertices[i];
        _mm_storeu_ps(&windowVertex.x, _mm_blend_ps(window, invW, 0b1000));  // x, y, z, invW
        _mm_storeu_ps(&windowVertex.color.x, _mm_loadu_ps(&vertices[i].color.x));
        windowVertex.fogCoord = 0.0f;  // (the stage sets it after the pass when fog is on)
    }
    return anyOutside;
}

}  // namespace glrenderer
