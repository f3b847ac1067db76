#include "thread_count.h"

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace glrenderer {

unsigned workerThreadCount() {
    if (const char* text = std::getenv("MYGL_THREADS")) {
        const long requested = std::strtol(text, nullptr, 10);
        if (requested >= 1 && requested <= 64) return static_cast<unsigned>(requested);
    }
    return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace glrenderer
