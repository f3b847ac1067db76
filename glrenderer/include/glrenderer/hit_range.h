#pragma once
#include <algorithm>

namespace glrenderer {

// GL_SELECT: whether anything drawn since the last hit record reached the view volume, and the
// least and greatest window depth of what did (of its vertices after clipping).
struct HitRange {
    bool hit = false;
    float minZ = 1.0f, maxZ = 0.0f;
    void add(float z) {
        hit = true;
        minZ = std::min(minZ, z);
        maxZ = std::max(maxZ, z);
    }
    void add(const HitRange& other) {
        if (!other.hit) return;
        add(other.minZ);
        add(other.maxZ);
    }
};

}  // namespace glrenderer
