#pragma once
// The lighting program (lighting_lanes.h) compiled for each lane width.
#include <span>

#include "glrenderer/lighting.h"

namespace glrenderer {

void lightVerticesScalar(const PreparedLighting& lighting, std::span<Vertex> vertices,
                         std::span<LightingOutputs> outputs, bool twoSided);
// Only after cpuHasAvx2Fma().
void lightVerticesAvx2(const PreparedLighting& lighting, std::span<Vertex> vertices, std::span<LightingOutputs> outputs,
                       bool twoSided);
// Only after cpuHasAvx512().
void lightVerticesAvx512(const PreparedLighting& lighting, std::span<Vertex> vertices,
                         std::span<LightingOutputs> outputs, bool twoSided);

}  // namespace glrenderer
