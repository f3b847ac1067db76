// glPushAttrib, glPopAttrib, glPushClientAttrib, glPopClientAttrib.
#include "attrib_stack.h"

#include "capabilities.h"
#include "compiled.h"

namespace mygl {

bool AttribStack::push(const Context::State& state, GLbitfield mask, std::span<const AttribGroup> groups) {
    if (entries_.size() == kMaxDepth) return false;
    std::vector<RestoreGroup> saved;
    for (const AttribGroup& group : groups) {
        if (!(mask & group.bit)) continue;
        if (!group.capabilities.empty()) {
            std::vector<std::pair<GLenum, bool>> enabled;
            for (GLenum cap : group.capabilities)
                enabled.emplace_back(cap, capabilityEnabled(state, cap).value_or(false));
            saved.emplace_back([enabled](Context::State& s) {
                for (const auto& [cap, on] : enabled) setCapability(s, cap, on);
            });
        }
        if (group.saveValues) saved.push_back(group.saveValues(state));
    }
    entries_.push_back(std::move(saved));
    return true;
}

std::optional<std::vector<RestoreGroup>> AttribStack::pop() {
    if (entries_.empty()) return std::nullopt;
    std::vector<RestoreGroup> saved = std::move(entries_.back());
    entries_.pop_back();
    return saved;
}

namespace {

void pushAttrib(Context::State* s, AttribStack& stack, GLbitfield mask, std::span<const AttribGroup> groups) {
    if (!stack.push(*s, mask, groups)) setError(*s, GL_STACK_OVERFLOW);
}

void popAttrib(Context::State* s, AttribStack& stack) {
    const std::optional<std::vector<RestoreGroup>> saved = stack.pop();
    if (!saved) return setError(*s, GL_STACK_UNDERFLOW);
    const glrenderer::DrawState before = *s->draw;
    for (const RestoreGroup& restore : *saved) restore(*s);
    updateLitColors(*s);
    s->lightingStale = true;  // the lights may have been restored
    updateClipPlanes(*s);     // so may the clip planes' equations
    // The batch keeps its own copy of the draw state, so it can end after the change.
    if (!(*s->draw == before)) endBatch(*s);
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glPushAttrib,
           +[](GLbitfield mask) {
               if (Context::State* s = stateOutsideBeginEnd())
                   pushAttrib(s, s->attribStack, mask, serverAttribGroups());
           }>(),
    listed<gl::glPopAttrib,
           +[]() {
               if (Context::State* s = stateOutsideBeginEnd()) popAttrib(s, s->attribStack);
           }>(),
    // Client state is not compiled into display lists.
    listed<gl::glPushClientAttrib,
           +[](GLbitfield mask) {
               if (Context::State* s = stateOutsideBeginEnd())
                   pushAttrib(s, s->clientAttribStack, mask, clientAttribGroups());
           }>(),
    listed<gl::glPopClientAttrib,
           +[]() {
               if (Context::State* s = stateOutsideBeginEnd()) popAttrib(s, s->clientAttribStack);
           }>(),
};

}  // namespace

std::span<const EntryPoint> attribStackEntryPoints() { return kEntryPoints; }

}  // namespace mygl
