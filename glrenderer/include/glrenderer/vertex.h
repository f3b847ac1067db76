#pragma once
#include <emmintrin.h>

#include <cstddef>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "glrenderer/matrix.h"

namespace glrenderer {

// A vertex as the program gives it: object-space position, RGBA colour (already clamped to
// [0, 1], as GL clamps a vertex's colour), normal and edge flag (which hides polygon edges in
// line and point mode). The pipeline's vertex stage transforms it with its batch's
// VertexTransform, on the pipeline's side. Lighting replaces the colour in place; its other
// outputs go to a LightingOutputs of their own, only for the batches that read them.
struct alignas(64) Vertex {
    glm::vec4 position;
    glm::vec4 color;
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 texCoord{0.0f, 0.0f, 0.0f, 1.0f};
    bool edgeFlag = true;
};
// Every vertex the program submits is written, then read by the batch thread: a cache line each.
static_assert(sizeof(Vertex) == 64);

// Writes `out` whole. `streaming`: with streaming stores, which bypass the caches, for a vertex
// that the batch thread reads on another core. An ordinary store first took the line back from
// that core (the chunks' arrays are reused), and in the host's slow phases that transfer was
// three quarters of the torus's program thread (frames 2.6 -> 8.5 ms; 5.2 ms streamed).
// BatchThread::post fences them before the hand-over. (Without that thread the vertex is read
// on this core, from its cache: streamed, it came back from memory.)
// The pipeline's passes over streamed vertices (the vertex stage, lighting) fetch each one's cache
// line this many vertices ahead: in bench-torus 42% of the vertex stage's samples, and in
// bench-lit-torus half of lighting's reads, waited on each vertex's first load.
inline constexpr std::size_t kVertexFetchAhead = 16;

// The position comes in a register (x, y, z, w): built in memory in parts and loaded whole, it
// waited on store forwarding.
[[gnu::always_inline]] inline void writeVertex(Vertex& out, __m128 position, const glm::vec4& color,
                                               const glm::vec3& normal, const glm::vec4& texCoord, bool edgeFlag,
                                               bool streaming) {
    const __m128 normalXY = _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(&normal.x)));
    const __m128 t = _mm_loadu_ps(&texCoord.x);
    const __m128 flag = _mm_castsi128_ps(_mm_cvtsi32_si128(edgeFlag ? 1 : 0));  // the bool's byte, padding zero
    const __m128 parts[4] = {
        position, _mm_loadu_ps(&color.x),
        _mm_movelh_ps(normalXY, _mm_unpacklo_ps(_mm_load_ss(&normal.z), t)),                          // nx ny nz s
        _mm_shuffle_ps(t, _mm_shuffle_ps(t, flag, _MM_SHUFFLE(0, 0, 3, 3)), _MM_SHUFFLE(2, 0, 2, 1))  // t r q, the flag
    };
    float* line = &out.position.x;
    for (int i = 0; i < 4; ++i) {
        if (streaming)
            _mm_stream_ps(line + 4 * i, parts[i]);
        else
            _mm_store_ps(line + 4 * i, parts[i]);
    }
}

// A lit vertex's colours besides its front colour, kept (BatchChunk::lightingOutputs) only for
// batches whose state reads them (needsLightingOutputs).
struct LightingOutputs {
    glm::vec4 backColor{0.0f};  // lit for the back face: with DrawState::twoSidedColors
    // The specular terms, front and back, with DrawState::secondaryColors (no alpha).
    glm::vec3 secondaryColor{0.0f}, backSecondaryColor{0.0f};
};

// The matrices a batch's vertices are transformed with.
struct VertexTransform {
    Matrix modelviewProjection = kIdentity;  // object to clip space
    Matrix modelview = kIdentity;            // object to eye space (for the seeds' culling methods)
    bool operator==(const VertexTransform&) const = default;
};

}  // namespace glrenderer
