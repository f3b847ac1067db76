#pragma once
#include <pmmintrin.h>
#include <xmmintrin.h>

namespace glrenderer {

// While alive, the calling thread flushes denormal results to zero and reads denormal operands
// as zero (MXCSR FTZ and DAZ), as the reference's whole draw does: its draw module sets both for
// every draw (vertex stage, clipper, triangle setup) and its rasterizer threads run with them.
// It shows where a clip-plane crossing's parameter is denormal (a vertex near FLT_MAX or w = 0):
// the crossing then lands on the vertex it is interpolated from. Every piece of pipeline work,
// on whichever thread it runs, is inside one.
class DenormalsAreZero {
public:
    DenormalsAreZero() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | _MM_FLUSH_ZERO_ON | _MM_DENORMALS_ZERO_ON); }
    ~DenormalsAreZero() { _mm_setcsr(saved_); }
    DenormalsAreZero(const DenormalsAreZero&) = delete;
    DenormalsAreZero& operator=(const DenormalsAreZero&) = delete;

private:
    unsigned saved_;
};

}  // namespace glrenderer
