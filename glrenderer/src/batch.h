#pragma once
#include <vector>

#include "glrenderer/draw_state.h"
#include "glrenderer/methods.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

// One draw as the reference sees it: consecutive submissions of one mode under one state,
// merged, with the methods in force when they were submitted.
struct Batch {
    DrawState state;
    Methods methods;
    PrimitiveMode mode = PrimitiveMode::Points;
    std::vector<Vertex> vertices;
};

}  // namespace glrenderer
