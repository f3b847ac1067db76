// Fog's per-draw constants and per-vertex coordinate, in the reference's arithmetic.
#include "fog.h"

#include <algorithm>
#include <cmath>

namespace glrenderer {

FogState makeFogState(FogMode mode, FogDistance distance, float density, float start, float end,
                      const glm::vec4& color) {
    FogState fog;
    fog.mode = mode;
    fog.distance = distance;
    // Mesa's STATE_FOG_PARAMS_OPTIMIZED: the linear constants in float (1 when end == start,
    // as a guard against the division), the exponential ones in double, then rounded.
    fog.linearScale = end == start ? 1.0f : -1.0f / (end - start);
    fog.linearBias = end * -fog.linearScale;
    constexpr double kLog2E = 1.44269504088896340736;         // 1 / ln 2
    constexpr double kOneOverSqrtLn2 = 1.201122408786449815;  // 1 / sqrt(ln 2)
    fog.expScale = static_cast<float>(density * (mode == FogMode::Exp2 ? kOneOverSqrtLn2 : kLog2E));
    for (int i = 0; i < 4; ++i) fog.color[i] = std::clamp(color[i], 0.0f, 1.0f);
    return fog;
}

float fogCoordinate(const Matrix& modelview, const glm::vec4& p, FogDistance distance) {
    const float x = p.x * at(modelview, 2, 0), y = p.y * at(modelview, 2, 1);
    const float z = p.z * at(modelview, 2, 2), w = p.w * at(modelview, 2, 3);
    // DP4 sums from the last component; the eye position's MUL and MADs from the first.
    const float eyeZ = distance == FogDistance::EyePosition ? ((x + y) + z) + w : ((w + z) + y) + x;
    return std::fabs(eyeZ);
}

void fogCoordinates(std::span<const Vertex> vertices, const Matrix& modelview, FogDistance distance,
                    std::span<float> out) {
    for (std::size_t i = 0; i < vertices.size(); ++i) out[i] = fogCoordinate(modelview, vertices[i].position, distance);
}

}  // namespace glrenderer
