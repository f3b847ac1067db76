#pragma once
// Line and polygon stipple on the GL side (stipple.cpp).
#include <optional>

#include "entry_points.h"

namespace mygl {

// glEnable/glDisable of GL_LINE_STIPPLE or GL_POLYGON_STIPPLE (false for other capabilities),
// and their glIsEnabled (nullopt for others).
bool setStippleCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> stippleCapability(const Context::State& state, GLenum cap);

}  // namespace mygl
