#pragma once
// How far two frames' colours are apart: the tests' comparison with OSMesa.
#include <algorithm>
#include <cstdlib>

#include "backends.h"

namespace testing_support {

// Pixels whose colour differs at all, and the largest channel difference.
struct ColorDifference {
    int pixels = 0;
    int maxChannel = 0;
};

inline ColorDifference difference(const Frame& a, const Frame& b) {
    ColorDifference d;
    for (std::size_t p = 0; p < a.color.size(); p += 4) {
        int most = 0;
        for (std::size_t c = 0; c < 4; ++c) most = std::max(most, std::abs(a.color[p + c] - b.color[p + c]));
        d.pixels += most > 0;
        d.maxChannel = std::max(d.maxChannel, most);
    }
    return d;
}

}  // namespace testing_support
