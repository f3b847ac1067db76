#pragma once
#include <cstddef>
#include <functional>
#include <vector>

namespace reference {

// Records the GL calls a program makes through the loaded GL table (<glad/gl.h>) so that the
// very same frame can be replayed on another backend: a program whose display code changes its
// own state (an animation counter, a toggle) is then compared on identical calls.
//
// Recorded: every call that changes GL state or draws (every function of the one list,
// <glcalls/gl11_calls.h>, but its queries), with the data behind pointer arguments copied as
// the list's count rules say. Queries (glGet*, glGetError, glIsEnabled, glReadPixels) pass
// through unrecorded.
class CallRecorder {
public:
    CallRecorder() = default;
    ~CallRecorder();
    CallRecorder(const CallRecorder&) = delete;
    CallRecorder& operator=(const CallRecorder&) = delete;

    // Wraps the currently loaded table: calls still reach its backend, and are recorded.
    // Only one recorder records at a time (std::logic_error otherwise).
    void start();
    // Puts the loaded table back as it was.
    void stop();
    // Calls every recorded function again, in order, through the table loaded now.
    void replay() const;

    std::size_t size() const { return calls_.size(); }
    void clear() { calls_.clear(); }

    // Used by the wrappers: appends one call.
    void add(std::function<void()> call) { calls_.push_back(std::move(call)); }

private:
    std::vector<std::function<void()>> calls_;
    bool recording_ = false;
};

}  // namespace reference
