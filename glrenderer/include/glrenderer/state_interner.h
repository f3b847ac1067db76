#pragma once
// Draw states as immutable shared objects: a batch points to the state it is drawn with, and
// two batches have the same state exactly when they point to the same object.
#include <array>
#include <cstddef>
#include <memory>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// A state no one can change: the program goes on changing its own copy while queued batches
// are drawn with this one.
using StateRef = std::shared_ptr<const DrawState>;

// Hands out one object per distinct state among the recently used ones, so that equal states
// (the usual case: a frame alternates a few) give the same pointer and allocate nothing. A state
// pushed out of the list lives on while a batch points to it; meeting it again makes a second
// object with the same value, so unequal pointers still need a comparison of the values.
class StateInterner {
public:
    StateRef intern(const DrawState& state);

private:
    static constexpr std::size_t kRecent = 16;
    std::array<StateRef, kRecent> recent_;  // most recently used first
};

}  // namespace glrenderer
