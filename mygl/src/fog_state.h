#pragma once
// Fog's state on the GL side (fog.cpp).
#include <optional>
#include <vector>

#include "entry_points.h"

namespace mygl {

// Forms the pipeline's fog (State::draw.fog) from State::fog, ending the batch if it changes.
void updateFog(Context::State& state);
// Which eye-space computation gives the fog coordinate under the current lighting: before each
// draw, as lighting decides it.
void updateFogDistance(Context::State& state);
// glGet's values of a fog parameter, or nullopt for other names.
std::optional<std::vector<double>> fogQuery(const Context::State& state, GLenum name);

}  // namespace mygl
