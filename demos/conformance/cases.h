#pragma once
// The generated conformance table: small GL 1.x drawings covering every combination of the
// state that decides pixels, plus random, sliver, tiny, huge and shared-edge triangles, and the
// API cases (every GL 1.1 function with its errors, api_table.h). Each case draws through the
// GL table, so it runs on either backend.
#include <functional>
#include <string>
#include <vector>

#include "observations.h"

namespace conformance {

struct Case {
    std::string category;  // e.g. "modes", "random", "slivers"
    std::string name;      // unique, usable as a file name
    bool flat;             // no interpolated color: bit-exact required
    std::function<void(int width, int height)> draw;
    // Calls made after `draw` whose errors and query answers must equal the reference's.
    std::function<void(Observations&)> observe = {};
};

inline constexpr int kWidth = 64, kHeight = 48;

std::vector<Case> allCases();
// The API cases alone (category "api-<group>", one case per row of the API table).
std::vector<Case> apiCases();

}  // namespace conformance
