#pragma once
#include <cstdint>

#include "clip_vertex.h"

namespace glrenderer {

// Cuts segment (a, b) in clip space to the view volume as the reference does: each end moves
// towards the other by the largest fraction any plane it is outside of asks for, with position
// and color interpolated in clip space from that end. Returns false when nothing is left (both
// ends outside one plane, the fractions meeting, or a non-finite distance). `outcodeA`/`B` are
// clipOutcode() of the ends.
bool clipLine(ClipVertex& a, ClipVertex& b, std::uint8_t outcodeA, std::uint8_t outcodeB);

}  // namespace glrenderer
