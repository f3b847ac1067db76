#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "reference/image.h"

namespace reference {

// How two frames of the same size differ, pixel by pixel, per 8-bit channel.
struct Comparison {
    long long pixels = 0;              // pixels compared
    long long differing = 0;           // pixels with any channel different
    long long differingMoreThan1 = 0;  // pixels with a channel differing by more than 1
    int maxChannelDifference = 0;
};

// Throws std::invalid_argument if the sizes differ.
Comparison compareImages(const Image& ours, const Image& reference);

// Pixels differing by more than `tolerance` in some channel where both depth buffers (as
// glReadPixels returns GL_UNSIGNED_INT depth) hold a written value equal within one unit of
// the 24-bit buffer: two surfaces tie there and the last bit of depth decides (DESIGN.md 4).
long long depthTies(const Image& ours, const Image& reference, const std::vector<std::uint32_t>& oursDepth,
                    const std::vector<std::uint32_t>& referenceDepth, int tolerance);

// Black where equal, gray where within 1, red (scaled by the difference) where more than 1.
Image diffImage(const Image& ours, const Image& reference);

// "pixels=N differing=N >1=N max=N"
std::string toString(const Comparison& comparison);

}  // namespace reference
