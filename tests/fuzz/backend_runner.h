#pragma once
// Runs a stream on MyGL and on OSMesa, each in a forked child of its own, so that a crash or a
// hang of either is an outcome rather than the end of the fuzzer.
#include <chrono>
#include <string>

#include "gl_call.h"

namespace fuzz {

enum class Backend { MyGL, OSMesa };
const char* backendName(Backend backend);

struct Outcome {
    enum class Status { Finished, Crashed, Hung };
    Status status = Status::Finished;
    int signal = 0;                // Crashed by a signal
    int exitCode = 0;              // Crashed by a non-zero exit (a sanitizer report, an exception)
    Answers answers;               // what the child sent back (all of it only when Finished)
    std::string describe() const;  // "finished", "SIGSEGV", "exit code 1", "hung"
};

struct BothOutcomes {
    Outcome mygl;
    Outcome osmesa;
};

// Each child makes a context of the stream's size current, clears it (colour 0, depth 1), runs
// the calls, then closes any open glBegin, drops pending errors and reads back every pixel's
// colour (RGBA8) and depth (GL_UNSIGNED_INT) after glFinish. A child still running after
// `timeout` is killed and reported as hung.
BothOutcomes runOnBothBackends(const Stream& stream, std::chrono::milliseconds timeout);

// What the child runs, without the fork: for a debugger, or a backend in this process.
Answers runStream(Backend backend, const Stream& stream);

}  // namespace fuzz
