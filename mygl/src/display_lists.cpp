#include "display_lists.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace mygl {

GLuint DisplayLists::generate(GLsizei range) {
    if (range <= 0) return 0;
    const auto count = static_cast<std::uint64_t>(range);
    // As the reference's name table: the names after the highest ever used while they last,
    // then the first gap of `count` free names.
    std::uint64_t first = std::uint64_t{highestName_} + 1;
    if (first + count - 1 > std::numeric_limits<GLuint>::max()) {
        first = 1;
        for (const auto& [name, calls] : lists_) {
            if (name >= first + count) break;
            first = std::uint64_t{name} + 1;
        }
        if (first + count - 1 > std::numeric_limits<GLuint>::max()) return 0;
    }
    for (std::uint64_t name = first; name < first + count; ++name) define(static_cast<GLuint>(name), {});
    return static_cast<GLuint>(first);
}

void DisplayLists::define(GLuint name, std::vector<CompiledCall> calls) {
    lists_[name] = std::move(calls);
    highestName_ = std::max(highestName_, name);
}

void DisplayLists::remove(GLuint first, GLsizei range) {
    const std::uint64_t last = std::uint64_t{first} + static_cast<std::uint64_t>(range);  // exclusive
    for (auto it = lists_.lower_bound(first); it != lists_.end() && it->first < last;) it = lists_.erase(it);
}

void DisplayLists::begin(GLuint name, GLenum mode) {
    compiling_ = true;
    name_ = name;
    mode_ = mode;
    building_.clear();
}

void DisplayLists::end() {
    define(name_, std::move(building_));
    building_ = {};
    compiling_ = false;
    name_ = 0;
    mode_ = 0;
}

void DisplayLists::call(GLuint name) {
    const auto found = lists_.find(name);
    if (found == lists_.end() || depth_ >= kMaxNesting) return;
    ++depth_;
    // A list may not change while it runs: only glNewList/glEndList/glDeleteLists change lists,
    // and none of them is compiled into one.
    for (const CompiledCall& call : found->second) call();
    --depth_;
}

}  // namespace mygl
