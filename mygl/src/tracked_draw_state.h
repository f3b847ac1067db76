#pragma once
// The pipeline's DrawState as a context keeps it.
#include <glrenderer/invariant.h>
#include <glrenderer/pipeline.h>
#include <glrenderer/state_interner.h>

namespace mygl {

// Changed in place by the state calls, through edit(); handed to the pipeline as an interned
// object, made again only after a change, so that a draw under unchanged state costs the
// pipeline a comparison of pointers.
class TrackedDrawState {
public:
    const glrenderer::DrawState& operator*() const { return state_; }
    const glrenderer::DrawState* operator->() const { return &state_; }
    // For a change: the next draw interns the state again.
    glrenderer::DrawState& edit() {
        interned_.reset();
        return state_;
    }
    const glrenderer::StateRef& interned(glrenderer::Pipeline& pipeline) {
        if (!interned_) interned_ = pipeline.intern(state_);
        // Every change went through edit(): interning again finds the same object (unless a
        // NaN makes the state unequal to itself: then no object is ever found again).
        MYGL_INVARIANT(!(state_ == state_) || interned_ == pipeline.intern(state_));
        return interned_;
    }

private:
    glrenderer::DrawState state_;
    glrenderer::StateRef interned_;
};

}  // namespace mygl
