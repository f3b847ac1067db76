#pragma once
#include <cstdint>

#include "glrenderer/draw_state.h"

namespace glrenderer {

inline bool depthPasses(CompareFunc func, std::uint32_t incoming, std::uint32_t stored) {
    switch (func) {
    case CompareFunc::Never: return false;
    case CompareFunc::Less: return incoming < stored;
    case CompareFunc::Equal: return incoming == stored;
    case CompareFunc::LessEqual: return incoming <= stored;
    case CompareFunc::Greater: return incoming > stored;
    case CompareFunc::NotEqual: return incoming != stored;
    case CompareFunc::GreaterEqual: return incoming >= stored;
    case CompareFunc::Always: return true;
    }
    return false;
}

}  // namespace glrenderer
