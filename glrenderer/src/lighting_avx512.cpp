#include "lighting_lanes.h"
#include "lighting_paths.h"
#include "simd_avx512.h"

namespace glrenderer {

void lightVerticesAvx512(const PreparedLighting& lighting, std::span<Vertex> vertices,
                         std::span<LightingOutputs> outputs, bool twoSided) {
    LightingProgram<Avx512Lanes>(lighting).lightVertices(vertices, outputs, twoSided);
}

}  // namespace glrenderer
