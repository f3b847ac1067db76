#pragma once
// The generated conformance table: small GL 1.x drawings covering every combination of the
// state that decides pixels, plus random, sliver, tiny, huge and shared-edge triangles. Each
// case draws through the GL table, so it runs on either backend.
#include <functional>
#include <string>
#include <vector>

namespace conformance {

struct Case {
    std::string category;  // e.g. "modes", "random", "slivers"
    std::string name;      // unique, usable as a file name
    bool flat;             // no interpolated color: bit-exact required
    std::function<void(int width, int height)> draw;
};

inline constexpr int kWidth = 64, kHeight = 48;

std::vector<Case> allCases();

}  // namespace conformance
