#pragma once
// Delta debugging of a failing stream: the shortest stream that still fails the same way.
#include <chrono>
#include <string>

#include "difference.h"

namespace fuzz {

struct ShrinkOptions {
    std::chrono::milliseconds timeout{20000};  // per run, as for the seed itself
    int maxTrials = 1500;
    std::chrono::seconds maxTime{180};
};

struct ShrinkResult {
    Stream stream;
    Difference difference;
    int trials = 0;
};

// Removes chunks of calls (halving the chunk size down to single calls), then shrinks the
// framebuffer, then simplifies arguments (to 0, 1, rounded values), keeping each step only
// while the stream fails with the same class (Difference::sameFailure).
ShrinkResult shrinkStream(const Stream& failing, const Difference& failure, const ShrinkOptions& options);

// The stream as a C snippet: the framebuffer size and the runner's prologue and epilogue in
// comments, one statement per call, the first differing call marked.
std::string toCSnippet(const Stream& stream, const Difference& difference);

}  // namespace fuzz
