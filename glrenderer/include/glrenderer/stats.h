#pragma once
#include <array>
#include <cstdint>
#include <functional>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// What the pipeline did, counted as the course assignment counted it. All counters add up:
// triangles = clippedAway + culledBack + culledFront + culledZeroArea + rasterized - clipCreated.
struct Stats {
    std::uint64_t vertices = 0;
    std::array<std::uint64_t, kPrimitiveModeCount> primitivesByMode{};
    std::uint64_t triangles = 0;    // after decomposition of every mode into triangles
    std::uint64_t clippedAway = 0;  // triangles entirely outside the view volume, or cut off
    std::uint64_t clipCreated = 0;  // extra triangles produced by clipping polygons
    std::uint64_t culledBack = 0;
    std::uint64_t culledFront = 0;
    std::uint64_t culledZeroArea = 0;
    std::uint64_t rasterized = 0;       // triangles that reached the rasterizer
    std::uint64_t fragments = 0;        // pixels covered by rasterized primitives
    std::uint64_t fragmentsPassed = 0;  // fragments that passed the depth test
    std::uint64_t pixelsWritten = 0;    // fragments that changed the color buffer
};

// Applies `op` counter by counter.
template <class Op>
Stats combineStats(const Stats& a, const Stats& b, Op op) {
    Stats r;
    r.vertices = op(a.vertices, b.vertices);
    for (std::size_t i = 0; i < r.primitivesByMode.size(); ++i)
        r.primitivesByMode[i] = op(a.primitivesByMode[i], b.primitivesByMode[i]);
    r.triangles = op(a.triangles, b.triangles);
    r.clippedAway = op(a.clippedAway, b.clippedAway);
    r.clipCreated = op(a.clipCreated, b.clipCreated);
    r.culledBack = op(a.culledBack, b.culledBack);
    r.culledFront = op(a.culledFront, b.culledFront);
    r.culledZeroArea = op(a.culledZeroArea, b.culledZeroArea);
    r.rasterized = op(a.rasterized, b.rasterized);
    r.fragments = op(a.fragments, b.fragments);
    r.fragmentsPassed = op(a.fragmentsPassed, b.fragmentsPassed);
    r.pixelsWritten = op(a.pixelsWritten, b.pixelsWritten);
    return r;
}

// What happened between two readings of the counters, e.g. around one draw.
inline Stats operator-(const Stats& later, const Stats& earlier) {
    return combineStats(later, earlier, std::minus<>{});
}

// The counts of two parts of the work together.
inline Stats operator+(const Stats& a, const Stats& b) { return combineStats(a, b, std::plus<>{}); }

}  // namespace glrenderer
