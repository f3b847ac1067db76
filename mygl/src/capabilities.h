#pragma once
// The capabilities glEnable/glDisable/glIsEnabled name, on a given context's state (the
// attribute stack saves and restores them too).
#include <optional>

#include "context_state.h"

namespace mygl {

// Sets capability `cap`, ending the batch if that changes what is drawn. False (and nothing
// changed) if MyGL does not know `cap`.
bool setCapability(Context::State& state, GLenum cap, bool enabled);

// Whether `cap` is enabled; nullopt if MyGL does not know it.
std::optional<bool> capabilityEnabled(const Context::State& state, GLenum cap);

}  // namespace mygl
