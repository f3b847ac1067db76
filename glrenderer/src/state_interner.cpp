#include "glrenderer/state_interner.h"

#include <algorithm>

namespace glrenderer {

StateRef StateInterner::intern(const DrawState& state) {
    auto found = std::find_if(recent_.begin(), recent_.end(), [&](const StateRef& r) { return r && *r == state; });
    if (found == recent_.end()) {
        found = recent_.end() - 1;
        *found = std::make_shared<const DrawState>(state);
    }
    std::rotate(recent_.begin(), found, found + 1);  // most recently used first
    return recent_.front();
}

}  // namespace glrenderer
