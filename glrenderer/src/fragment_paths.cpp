#include "fragment_paths.h"

#include <cstdlib>

#include "cpu_features.h"

namespace glrenderer {

const FragmentRoutine& FragmentPaths::routine(FragmentKey key) const {
    for (const FastPath& fast : fast_) {
        if (fast.key == key) return fast.routine;
    }
    return anyKey_;
}

FragmentChoice::FragmentChoice(const FragmentPaths& paths, FragmentKey key) {
    varyingW = {key, &paths.routine(key)};
    if (key.shading == Shading::Perspective) key.shading = Shading::Linear;
    constantW = {key, &paths.routine(key)};
}

const FragmentPath& FragmentChoice::path(const AttributePlane& invW) const {
    // The plane (1, 0, 0) is 1 at every pixel, and x * 1 is x for every float x.
    const bool constantOne = invW.a0 == 1.0f && invW.dadx == 0.0f && invW.dady == 0.0f;
    return constantOne ? constantW : varyingW;
}

const FragmentPaths& bestFragmentPaths() {
    static const FragmentPaths& best = []() -> const FragmentPaths& {
        const char* cap = std::getenv("MYGL_KERNELS");
        const std::string_view limit = cap ? cap : "";
        if (cpuHasAvx512() && limit != "avx2" && limit != "scalar") return avx512FragmentPaths();
        if (cpuHasAvx2Fma() && limit != "scalar") return avx2FragmentPaths();
        return scalarFragmentPaths();
    }();
    return best;
}

}  // namespace glrenderer
