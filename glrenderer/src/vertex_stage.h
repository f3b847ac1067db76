#pragma once
#include <cstdint>
#include <span>

#include "glrenderer/vertex.h"
#include "window_vertex.h"

namespace glrenderer {

// The vertex stage of a batch: each vertex's clip outcode (clipOutcode) and window position
// (ViewportTransform::apply), into arrays as long as `vertices`. Returns the union of the
// outcodes. CPUs with FMA take a version that works on a vertex's four coordinates at once
// (without FMA, apply()'s fused multiply-adds are library calls); the bits are the same.
std::uint8_t transformVertices(std::span<const Vertex> vertices, const ViewportTransform& viewport,
                               std::uint8_t* outcodes, WindowVertex* windowVertices);

// The version for CPUs with FMA, compiled for them; only call it after cpuHasFma().
std::uint8_t transformVerticesFma(std::span<const Vertex> vertices, const ViewportTransform& viewport,
                                  std::uint8_t* outcodes, WindowVertex* windowVertices);

}  // namespace glrenderer
