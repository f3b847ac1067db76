#pragma once
// How far two frames are apart: the tests' comparison with OSMesa.
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

// Pixels whose colour or depth differs at all.
inline int differingPixels(const Frame& a, const Frame& b) {
    int pixels = 0;
    for (std::size_t p = 0; p < a.depth.size(); ++p) {
        bool differs = a.depth[p] != b.depth[p];
        for (std::size_t c = 0; c < 4; ++c) differs = differs || a.color[4 * p + c] != b.color[4 * p + c];
        pixels += differs;
    }
    return pixels;
}

}  // namespace testing_support
