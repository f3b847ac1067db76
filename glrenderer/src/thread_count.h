#pragma once

namespace glrenderer {

// Threads a pipeline works with: MYGL_THREADS if set (1 to 64, as llvmpipe's LP_NUM_THREADS),
// else one per CPU. With 1, everything runs on the caller's thread.
unsigned workerThreadCount();

}  // namespace glrenderer
