#pragma once
// The seed documents' culling methods, decided on the triangle as submitted (before clipping),
// as the course did. GL's rule, the sign of the snapped window area, lives in triangle_setup.h.
#include "glrenderer/methods.h"
#include "clip_vertex.h"
#include "triangle_setup.h"

namespace glrenderer {

// Facing of (a, b, c) by `method` (not WindowArea), from the eye-space data the vertices carry.
Facing seedFacing(CullMethod method, const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, bool frontFaceCCW);

}  // namespace glrenderer
