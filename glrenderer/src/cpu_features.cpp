#include "cpu_features.h"

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
    static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma");
    return has;
}
#else
bool cpuHasFma() { return false; }
bool cpuHasAvx2Fma() { return false; }
bool cpuHasAvx512() { return false; }
#endif

}  // namespace glrenderer
