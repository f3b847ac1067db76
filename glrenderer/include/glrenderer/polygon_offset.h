#pragma once

namespace glrenderer {

// glPolygonOffset and the three GL_POLYGON_OFFSET_* enables.
struct PolygonOffset {
    float factor = 0.0f, units = 0.0f;
    bool fill = false, line = false, point = false;
    bool operator==(const PolygonOffset&) const = default;
};

}  // namespace glrenderer
