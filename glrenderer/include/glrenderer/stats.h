#pragma once
#include <array>
#include <cstdint>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// What the pipeline did, counted as the course assignment counted it. All counters add up:
// triangles = clippedAway + culledBack + culledFront + culledZeroArea + rasterized - clipCreated.
struct Stats {
    std::uint64_t vertices = 0;
    std::array<std::uint64_t, kPrimitiveModeCount> primitivesByMode{};
    std::uint64_t triangles = 0;       // after decomposition of every mode into triangles
    std::uint64_t clippedAway = 0;     // triangles entirely outside the view volume, or cut off
    std::uint64_t clipCreated = 0;     // extra triangles produced by clipping polygons
    std::uint64_t culledBack = 0;
    std::uint64_t culledFront = 0;
    std::uint64_t culledZeroArea = 0;
    std::uint64_t rasterized = 0;      // triangles that reached the rasterizer
    std::uint64_t fragments = 0;       // pixels covered by rasterized primitives
    std::uint64_t fragmentsPassed = 0; // fragments that passed the depth test
    std::uint64_t pixelsWritten = 0;   // fragments that changed the color buffer
};

// What happened between two readings of the counters, e.g. around one draw.
inline Stats operator-(const Stats& later, const Stats& earlier) {
    Stats d;
    d.vertices = later.vertices - earlier.vertices;
    for (std::size_t i = 0; i < d.primitivesByMode.size(); ++i)
        d.primitivesByMode[i] = later.primitivesByMode[i] - earlier.primitivesByMode[i];
    d.triangles = later.triangles - earlier.triangles;
    d.clippedAway = later.clippedAway - earlier.clippedAway;
    d.clipCreated = later.clipCreated - earlier.clipCreated;
    d.culledBack = later.culledBack - earlier.culledBack;
    d.culledFront = later.culledFront - earlier.culledFront;
    d.culledZeroArea = later.culledZeroArea - earlier.culledZeroArea;
    d.rasterized = later.rasterized - earlier.rasterized;
    d.fragments = later.fragments - earlier.fragments;
    d.fragmentsPassed = later.fragmentsPassed - earlier.fragmentsPassed;
    d.pixelsWritten = later.pixelsWritten - earlier.pixelsWritten;
    return d;
}

}  // namespace glrenderer
