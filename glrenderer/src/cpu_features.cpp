#include "cpu_features.h"

#include <cstdlib>
#include <string_view>

namespace glrenderer {

#if defined(__x86_64__) || defined(__i386__)
bool cpuHasFma() {
    static const bool has = __builtin_cpu_supports("fma") && __builtin_cpu_supports("sse4.1");
    return has;
}

bool cpuHasAvx2Fma() {
    static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return has;
}

bool cpuHasAvx512() {
    static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                            __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512cd") &&
                            __builtin_cpu_supports("fma");
    return has;
}
#else
bool cpuHasFma() { return false; }
bool cpuHasAvx2Fma() { return false; }
bool cpuHasAvx512() { return false; }
#endif

LaneWidth widestLanes() {
    static const LaneWidth widest = [] {
        const char* cap = std::getenv("MYGL_KERNELS");
        const std::string_view limit = cap ? cap : "";
        if (cpuHasAvx512() && limit != "avx2" && limit != "scalar") return LaneWidth::Avx512;
        if (cpuHasAvx2Fma() && limit != "scalar") return LaneWidth::Avx2;
        return LaneWidth::Scalar;
    }();
    return widest;
}

}  // namespace glrenderer
