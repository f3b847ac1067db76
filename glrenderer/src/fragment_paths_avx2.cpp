// The fragment routines in 8 lanes of AVX2 with FMA. Compiled with -mavx2 -mfma; called only
// after cpuHasAvx2Fma().
#include "fragment_routines.h"
#include "simd_avx2.h"

namespace glrenderer {

const FragmentPaths& avx2FragmentPaths() { return fragmentPathsOf<Avx2Lanes>(); }

}  // namespace glrenderer
