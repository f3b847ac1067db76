// The fragment routines one pixel at a time, for any CPU; their routine for any key is the
// general path.
#include "fragment_routines.h"
#include "simd_scalar.h"

namespace glrenderer {

const FragmentPaths& scalarFragmentPaths() { return fragmentPathsOf<ScalarLanes>(); }

}  // namespace glrenderer
