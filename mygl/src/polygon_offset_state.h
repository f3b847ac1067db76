#pragma once
// Polygon offset's enables on the GL side (polygon_offset.cpp).
#include <optional>

#include "entry_points.h"

namespace mygl {

// glEnable/glDisable of GL_POLYGON_OFFSET_FILL, _LINE or _POINT (false for other capabilities),
// and their glIsEnabled (nullopt for others).
bool setPolygonOffsetCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> polygonOffsetCapability(const Context::State& state, GLenum cap);

}  // namespace mygl
