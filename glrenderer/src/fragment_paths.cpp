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

FragmentChoice::FragmentChoice(const FragmentPaths& paths, FragmentKey key, const DrawState& state)
    : FragmentChoice(paths, key) {
    fog = state.fog;
    polygonOffset = state.polygonOffset;
    texture = state.texture.texture.get();
    textureEnvColor = state.texture.envColor;
}

FragmentChoice::FragmentChoice(const FragmentPaths& paths, FragmentKey key) {
    varyingW = {key, &paths.routine(key)};
    if (key.shading == Shading::Perspective) key.shading = Shading::Linear;
    constantW = {key, &paths.routine(key)};
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
