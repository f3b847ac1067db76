#pragma once

namespace glrenderer {

// What the CPU the program runs on can execute: the files compiled for FMA, AVX2 or AVX-512
// are called only after these say yes. Each answer is computed once.
bool cpuHasFma();      // FMA3 (and SSE4.1, which every FMA CPU has)
bool cpuHasAvx2Fma();  // AVX2 and FMA3
bool cpuHasAvx512();   // AVX-512F and FMA3

}  // namespace glrenderer
