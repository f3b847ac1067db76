#pragma once
// The per-fragment operations on the GL side (fragment_ops.cpp, issue 16): scissor, alpha
// test, stencil, blending, logic op, colour mask.
#include <optional>
#include <vector>

#include "entry_points.h"

namespace mygl {

// glEnable/glDisable of GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND,
// GL_COLOR_LOGIC_OP or GL_INDEX_LOGIC_OP (false for other capabilities), and their glIsEnabled
// (nullopt for others).
bool setFragmentOpsCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> fragmentOpsCapability(const Context::State& state, GLenum cap);
// glGet's values of the operations' parameters, or nullopt for other names.
std::optional<std::vector<double>> fragmentOpsQuery(const Context::State& state, GLenum name);

}  // namespace mygl
