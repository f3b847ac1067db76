#pragma once

namespace glrenderer {

// What the CPU the program runs on can execute: the files compiled for FMA, AVX2 or AVX-512
// are called only after these say yes. Each answer is computed once.
bool cpuHasFma();      // FMA3 (and SSE4.1, which every FMA CPU has)
bool cpuHasAvx2Fma();  // AVX2 and FMA3
bool cpuHasAvx512();   // AVX-512F, AVX-512BW, AVX-512VL, AVX-512CD and FMA3

// The widest lanes (simd_*.h) the stages run on this CPU, chosen once. MYGL_KERNELS=avx2 or
// scalar caps the choice, to see how a CPU without AVX-512 (or AVX2) would run: the results
// are the same.
enum class LaneWidth { Scalar, Avx2, Avx512 };
LaneWidth widestLanes();

}  // namespace glrenderer
