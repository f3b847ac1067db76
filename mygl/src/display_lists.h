#pragma once
// Display lists: the calls a list was compiled from, kept with copies of the data behind their
// pointer arguments, replayed through MyGL's own implementations by glCallList.
#include <glad/gl.h>

#include <cstddef>
#include <functional>
#include <map>
#include <vector>

namespace mygl {

using CompiledCall = std::function<void()>;

class DisplayLists {
public:
    // The reference's limit on glCallList nesting (calls deeper than this are ignored).
    static constexpr int kMaxNesting = 64;

    // `range` consecutive unused names, each now an empty list (as the reference makes them, so
    // that glIsList is true for them), or 0 when there are none. Deleted names are not reused
    // while there are names above the highest ever used, as in the reference.
    GLuint generate(GLsizei range);
    void remove(GLuint first, GLsizei range);
    bool exists(GLuint name) const { return lists_.contains(name); }

    // Compiling: calls go into a new list that replaces `name` at end().
    bool compiling() const { return compiling_; }
    bool executingWhileCompiling() const { return mode_ == GL_COMPILE_AND_EXECUTE; }
    GLuint compilingName() const { return compiling_ ? name_ : 0; }
    GLenum compilingMode() const { return compiling_ ? mode_ : 0; }
    void begin(GLuint name, GLenum mode);
    void add(CompiledCall call) { building_.push_back(std::move(call)); }
    void end();

    // Runs the list's calls; nothing for a name without a list or past kMaxNesting.
    void call(GLuint name);
    bool replaying() const { return depth_ > 0; }

    GLuint base = 0;  // glListBase, added to the names of glCallLists

private:
    void define(GLuint name, std::vector<CompiledCall> calls);

    std::map<GLuint, std::vector<CompiledCall>> lists_;
    GLuint highestName_ = 0;
    bool compiling_ = false;
    GLuint name_ = 0;
    GLenum mode_ = 0;
    std::vector<CompiledCall> building_;
    int depth_ = 0;
};

}  // namespace mygl
