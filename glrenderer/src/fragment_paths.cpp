#include "fragment_paths.h"

#include "cpu_features.h"

namespace glrenderer {

const FragmentRoutine& FragmentPaths::routine(FragmentKey key) const {
    if (lodPaths_ && key.samplesLod()) return lodPaths_().routine(key);
    for (const FastPath& fast : fast_) {
        if (fast.key == key) return fast.routine;
    }
    return anyKey_;
}

FragmentChoice::FragmentChoice(const FragmentPaths& paths, FragmentKey key, const DrawState& state)
    : FragmentChoice(paths, key) {
    fog = state.fog;
    polygonOffset = state.polygonOffset;
    ops = FragmentOpsConstants::of(state.fragmentOps);
    scissor = state.fragmentOps.scissor;
    polygonStipple = state.polygonStipple.pattern;
    texture = state.texture.texture.get();
    textureEnvColor = state.texture.envColor;
    textureBorderColor = state.texture.borderColor;
}

FragmentChoice::FragmentChoice(const FragmentPaths& paths, FragmentKey key) {
    varyingW = {key, &paths.routine(routineKey(key))};
    if (key.shading == Shading::Perspective) key.shading = Shading::Linear;
    constantW = {key, &paths.routine(routineKey(key))};
}

const FragmentPaths& bestFragmentPaths() {
    static const FragmentPaths& best = []() -> const FragmentPaths& {
        switch (widestLanes()) {
        case LaneWidth::Avx512: return avx512FragmentPaths();
        case LaneWidth::Avx2: return avx2FragmentPaths();
        case LaneWidth::Scalar: break;
        }
        return scalarFragmentPaths();
    }();
    return best;
}

}  // namespace glrenderer
