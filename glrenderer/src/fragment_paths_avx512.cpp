// The fragment routines in 16 lanes of AVX-512F and BW. Compiled with -mavx512f -mavx512bw
// -mfma; called only after cpuHasAvx512().
#include "fragment_routines.h"
#include "simd_avx512.h"

namespace glrenderer {

const FragmentPaths& avx512FragmentPaths() {
    return fragmentPathsOf<Avx512Lanes, &avx2EvexFragmentPaths, FastKeys::WithoutLod>();
}

}  // namespace glrenderer
