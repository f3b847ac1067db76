#pragma once
// Random GL call streams from a seed: sane scenes mixed with bad input.
#include <cstdint>
#include <map>
#include <string>

#include "gl_call.h"

namespace fuzz {

struct GeneratorOptions {
    int sizeMax = 300;  // framebuffers are 1x1 up to sizeMax x sizeMax
};

// Calls the generator dropped because a reference-departure rule matched them, by rule name.
using AvoidedCounts = std::map<std::string, std::size_t>;

// The same seed gives the same stream on every run and machine (std::mt19937_64 and our own
// mapping of its bits to values; no standard distributions, whose output is unspecified).
Stream generateStream(std::uint64_t seed, const GeneratorOptions& options, AvoidedCounts& avoided);

}  // namespace fuzz
