#pragma once
#include "context_state.h"

namespace mygl {

// GL_SELECT: writes a hit record of what was hit since the last one (draws and raster
// positions), if anything was, under the current names.
void writeHitRecord(Context::State& state);

}  // namespace mygl
