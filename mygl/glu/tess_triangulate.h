#pragma once
// Triangulates one face of the arrangement: a counter-clockwise outer boundary minus clockwise
// holes. Holes are joined to the boundary by bridges, then ears are clipped. Uses only the face's
// own vertices (no new ones) and always terminates, also on rounding-damaged input.
#include <array>
#include <vector>

#include "tess_arrangement.h"

namespace mygl::glu::tess {

using Triangle = std::array<int, 3>;  // vertex indices, counter-clockwise

std::vector<Triangle> triangulateFace(const std::vector<Vertex>& vertices, std::vector<int> outer,
                                      std::vector<std::vector<int>> holes);

}  // namespace mygl::glu::tess
