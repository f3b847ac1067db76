#pragma once
#include <immintrin.h>

#include <chrono>

namespace glrenderer {

// Spins until ready() or until `budget` has passed, and returns ready()'s last answer: a thread
// about to block on a condition variable spins first. On a virtual machine a blocked thread's
// core halts, and in the host's busy phases waking it again took long enough to triple a
// torus's frame, whose waits for the other thread are mostly a few microseconds.
template <class Ready>
bool spinUntil(Ready&& ready, std::chrono::nanoseconds budget) {
    const auto deadline = std::chrono::steady_clock::now() + budget;
    for (;;) {
        for (int i = 0; i < 32; ++i) {
            if (ready()) return true;
            _mm_pause();
        }
        if (std::chrono::steady_clock::now() >= deadline) return ready();
    }
}

}  // namespace glrenderer
