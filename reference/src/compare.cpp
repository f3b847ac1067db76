#include "reference/compare.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace reference {
namespace {

void requireSameSize(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size()) {
        throw std::invalid_argument("images of different sizes cannot be compared");
    }
}

int pixelDifference(const Image& a, const Image& b, std::size_t pixel) {
    int worst = 0;
    for (std::size_t c = 0; c < 4; ++c) {
        worst = std::max(worst, std::abs(int{a.rgba[pixel * 4 + c]} - int{b.rgba[pixel * 4 + c]}));
    }
    return worst;
}

}  // namespace

Comparison compareImages(const Image& ours, const Image& reference) {
    requireSameSize(ours, reference);
    Comparison result;
    result.pixels = static_cast<long long>(ours.rgba.size() / 4);
    for (std::size_t p = 0; p < ours.rgba.size() / 4; ++p) {
        const int difference = pixelDifference(ours, reference, p);
        result.differing += difference > 0;
        result.differingMoreThan1 += difference > 1;
        result.maxChannelDifference = std::max(result.maxChannelDifference, difference);
    }
    return result;
}

long long depthTies(const Image& ours, const Image& reference, const std::vector<std::uint32_t>& oursDepth,
                    const std::vector<std::uint32_t>& referenceDepth, int tolerance) {
    requireSameSize(ours, reference);
    if (oursDepth.size() != ours.rgba.size() / 4 || referenceDepth.size() != oursDepth.size()) {
        throw std::invalid_argument("depth buffers do not match the images");
    }
    long long ties = 0;
    for (std::size_t p = 0; p < oursDepth.size(); ++p) {
        const long long a = oursDepth[p] >> 8, b = referenceDepth[p] >> 8;
        const bool written = a != 0xFFFFFF;  // not the cleared far value: a surface is there
        ties += pixelDifference(ours, reference, p) > tolerance && written && std::llabs(a - b) <= 1;
    }
    return ties;
}

Image diffImage(const Image& ours, const Image& reference) {
    requireSameSize(ours, reference);
    Image diff{ours.width, ours.height, std::vector<std::uint8_t>(ours.rgba.size(), 0)};
    for (std::size_t p = 0; p < ours.rgba.size() / 4; ++p) {
        const int difference = pixelDifference(ours, reference, p);
        std::uint8_t* out = &diff.rgba[p * 4];
        out[3] = 255;
        if (difference == 1) {
            out[0] = out[1] = out[2] = 96;
        } else if (difference > 1) {
            out[0] = static_cast<std::uint8_t>(std::min(255, 128 + difference));
        }
    }
    return diff;
}

std::string toString(const Comparison& c) {
    return "pixels=" + std::to_string(c.pixels) + " differing=" + std::to_string(c.differing) +
           " >1=" + std::to_string(c.differingMoreThan1) + " max=" + std::to_string(c.maxChannelDifference);
}

}  // namespace reference
