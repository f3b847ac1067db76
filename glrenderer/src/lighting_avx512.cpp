#include "lighting_lanes.h"
#include "lighting_paths.h"
#include "simd_avx512.h"

namespace glrenderer {

void lightVerticesAvx512(const PreparedLighting& lighting, std::span<Vertex> vertices, bool twoSided) {
    LightingProgram<Avx512Lanes>(lighting).lightVertices(vertices, twoSided);
}

}  // namespace glrenderer
