#pragma once
#include <cstdint>

#include "clip.h"
#include "clip_vertex.h"

namespace glrenderer {

// Cuts segment (a, b) in clip space to the clip planes as the reference does: each end moves
// towards the other by the largest fraction any plane it is outside of asks for, with position
// and color interpolated in clip space from that end. Returns false when nothing is left (both
// ends outside one plane, the fractions meeting, or a non-finite distance). `outcodeA`/`B` are
// clipOutcode() of the ends, with the program's planes `user`.
bool clipLine(ClipVertex& a, ClipVertex& b, Outcode outcodeA, Outcode outcodeB, const UserClipPlanes& user);

}  // namespace glrenderer
