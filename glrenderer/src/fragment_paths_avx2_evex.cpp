// The 8-lane AVX2 fragment routines compiled for AVX-512VL: an AVX-512 machine's routines for
// keys that sample a texture's level of detail (avx512FragmentPaths' lodPaths). With 32
// registers the sampler's lanes stay out of the stack. Compiled with -mavx2 -mfma -mavx512f
// -mavx512vl -mavx512bw -mavx512cd; called only after cpuHasAvx512().
#include "fragment_routines.h"
#include "simd_avx2.h"
#include "simd_avx512.h"

namespace glrenderer {

// Tiny triangles' coverage in 16 lanes, as many pixels as AVX-512's narrow blocks hold: the
// 8-lane layout holds few of a triangle a few pixels across.
template <>
struct CoverageLanesOf<Avx2LanesOf<true>> {
    using type = Avx512Lanes;
};

const FragmentPaths& avx2EvexFragmentPaths() {
    return fragmentPathsOf<Avx2LanesOf<true>, nullptr, FastKeys::WithLod>();
}

}  // namespace glrenderer
