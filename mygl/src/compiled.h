#pragma once
// Entry points of commands that go into display lists. While a list is being compiled the call
// is kept in it (with a copy of the data behind a pointer argument: `Count` elements) and, in
// GL_COMPILE mode, not executed. The implementation is a template argument, so that it is
// inlined into the entry point and the check costs one branch.
#include <array>
#include <tuple>
#include <type_traits>
#include <vector>

#include "entry_points.h"

namespace mygl {

// An argument kept for replay: a value as it is; for a pointer to const data, the `Count`
// elements behind it (the program's memory may change or be gone when the list runs).
template <class T>
struct KeptArgument {
    T value;
    KeptArgument(T v, std::size_t) : value(v) {}
    T get() const { return value; }
};
template <class T>
struct KeptArgument<const T*> {
    std::vector<T> data;
    bool null;
    KeptArgument(const T* p, std::size_t count) : data(p ? std::vector<T>(p, p + count) : std::vector<T>()), null(!p) {}
    const T* get() const { return null ? nullptr : data.data(); }
};

// `Count`: a number, or a function of the call's arguments giving it (glLightfv's count
// depends on its parameter name).
template <auto Implementation, auto Count, class Pointer = decltype(Implementation)>
struct Compiled;
template <auto Implementation, auto Count, class R, class... Args>
struct Compiled<Implementation, Count, R (*)(Args...)> {
    [[gnu::flatten]] static R call(Args... args) {
        if (Context::State* s = currentState(); s && s->lists.compiling()) [[unlikely]] {
            keep(*s, args...);
            if (!s->lists.executingWhileCompiling()) return R();
        }
        return Implementation(args...);
    }

    // Out of line, so that the usual path (not compiling) saves no registers for it.
    [[gnu::noinline, gnu::cold]] static void keep(Context::State& s, Args... args) {
        std::size_t count = 0;
        if constexpr (std::is_invocable_v<decltype(Count), Args...>)
            count = Count(args...);
        else
            count = Count;
        s.lists.add([kept = std::make_tuple(KeptArgument<Args>(args, count)...)] {
            std::apply([](const auto&... k) { Implementation(k.get()...); }, kept);
        });
    }
};

// The entry point of a command that display lists compile; `Count`: the elements behind its
// pointer arguments.
template <auto Implementation, auto Count = std::size_t{0}>
ProcAddress compiled() {
    return entry(&Compiled<Implementation, Count>::call);
}

// The 2, 3 and 4 component forms of a position call (glVertex, glRasterPos) in type T and their
// vector forms, each calling `function(const T* components, int count)`.
// clang-format off
#define MYGL_POSITION_ENTRIES(name, suffix, T, function)                                            \
    {name "2" #suffix, compiled<+[](T x, T y) { function(std::array<T, 2>{x, y}.data(), 2); }>()},        \
    {name "3" #suffix, compiled<+[](T x, T y, T z) { function(std::array<T, 3>{x, y, z}.data(), 3); }>()}, \
    {name "4" #suffix, compiled<+[](T x, T y, T z, T w) { function(std::array<T, 4>{x, y, z, w}.data(), 4); }>()}, \
    {name "2" #suffix "v", compiled<+[](const T* v) { function(v, 2); }, 2>()},                                \
    {name "3" #suffix "v", compiled<+[](const T* v) { function(v, 3); }, 3>()},                                \
    {name "4" #suffix "v", compiled<+[](const T* v) { function(v, 4); }, 4>()}
// clang-format on

}  // namespace mygl
