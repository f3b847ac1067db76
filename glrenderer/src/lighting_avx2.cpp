#include "lighting_lanes.h"
#include "lighting_paths.h"
#include "simd_avx2.h"

namespace glrenderer {

void lightVerticesAvx2(const PreparedLighting& lighting, std::span<Vertex> vertices, std::span<LightingOutputs> outputs,
                       bool twoSided) {
    LightingProgram<Avx2Lanes>(lighting).lightVertices(vertices, outputs, twoSided);
}

}  // namespace glrenderer
