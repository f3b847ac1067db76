#include "seed_culling.h"

#include <glm/geometric.hpp>

namespace glrenderer {

Facing seedFacing(CullMethod method, const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, bool frontFaceCCW) {
    if (method == CullMethod::LookVector) {
        // Seed 003: the first vertex's normal against the look vector (0, 0, -1). Right for an
        // orthographic view; under perspective the direction to the triangle is not the look
        // vector, so triangles near the edges of the view are judged wrongly.
        const float toward = -a.normal.z;
        if (toward == 0.0f) return Facing::ZeroArea;
        return toward < 0.0f ? Facing::Front : Facing::Back;
    }
    // Seed 000: the face normal against the vector from the eye (at the origin) to the triangle.
    const glm::vec3 normal = glm::cross(b.eye - a.eye, c.eye - a.eye);
    const float side = glm::dot(normal, a.eye);
    if (side == 0.0f) return Facing::ZeroArea;
    const bool counterClockwise = side < 0.0f;
    return counterClockwise == frontFaceCCW ? Facing::Front : Facing::Back;
}

}  // namespace glrenderer
