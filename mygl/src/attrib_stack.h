#pragma once
// The attribute stacks: glPushAttrib/glPopAttrib save and restore groups of server state,
// glPushClientAttrib/glPopClientAttrib groups of client state.
#include <glad/gl.h>

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "mygl/context.h"

namespace mygl {

// Puts back what a push saved of one attribute group.
using RestoreGroup = std::function<void(Context::State&)>;

// An attribute group (GL_LINE_BIT, ...): the capabilities (glEnable) it saves, and a function
// saving its other values (or null).
struct AttribGroup {
    GLbitfield bit;
    std::span<const GLenum> capabilities;
    RestoreGroup (*saveValues)(const Context::State&);
};

// The groups glPushAttrib and glPushClientAttrib know (attrib_groups.cpp).
std::span<const AttribGroup> serverAttribGroups();
std::span<const AttribGroup> clientAttribGroups();

class AttribStack {
public:
    // GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, as the reference has them.
    static constexpr std::size_t kMaxDepth = 16;

    std::size_t depth() const { return entries_.size(); }
    // Saves every group of `groups` whose bit `mask` has; false (nothing saved) when full.
    bool push(const Context::State& state, GLbitfield mask, std::span<const AttribGroup> groups);
    // What the last push saved, in the order it saved it; nullopt when empty.
    std::optional<std::vector<RestoreGroup>> pop();

private:
    std::vector<std::vector<RestoreGroup>> entries_;
};

}  // namespace mygl
