#pragma once
// MYGL_INVARIANT(condition): a fact the code relies on that its types cannot state (a count
// within a fixed array, a rectangle within the framebuffer). Checked in builds configured with
// MYGL_CHECK_INVARIANTS (Debug builds and the sanitizer build CI runs the tests under), where a
// broken one names itself and aborts; compiled out otherwise, so it costs nothing where speed
// is measured.
#ifdef MYGL_CHECK_INVARIANTS
#include <cstdio>
#include <cstdlib>

namespace glrenderer::detail {
[[noreturn]] inline void invariantBroken(const char* condition, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: MyGL invariant broken: %s\n", file, line, condition);
    std::abort();
}
}  // namespace glrenderer::detail

#define MYGL_INVARIANT(condition) \
    ((condition) ? static_cast<void>(0) : ::glrenderer::detail::invariantBroken(#condition, __FILE__, __LINE__))
#else
#define MYGL_INVARIANT(condition) static_cast<void>(0)
#endif
