#pragma once
// Entry points made from the one list of GL functions (glcalls/gl11_calls.h). listed<gl::NAME,
// implementation>() gives NAME the wrapper its list class asks for: a command the list says is
// compiled is kept in a display list being compiled (with its pointer data copied by the list's
// count rule) and, in GL_COMPILE mode, not executed; the other classes (dereferenced: the
// implementation keeps what it read itself; immediate; query) call the implementation directly.
// The implementation is a template argument, so that it is inlined into the entry point and the
// check costs one branch.
#include <glcalls/gl11_calls.h>
#include <glcalls/kept_argument.h>

#include <array>
#include <tuple>
#include <type_traits>

#include "entry_points.h"

namespace mygl {

template <auto Implementation, auto Count, class Pointer = decltype(Implementation)>
struct Compiled;
template <auto Implementation, auto Count, class R, class... Args>
struct Compiled<Implementation, Count, R (*)(Args...)> {
    static_assert(std::is_invocable_v<decltype(Count), Args...> || std::is_integral_v<decltype(Count)>,
                  "the list's count rule does not take this function's arguments");
    static_assert(!(std::is_pointer_v<Args> || ...) || std::is_invocable_v<decltype(Count), Args...> || Count != 0,
                  "the list gives no element count for this function's pointer argument");

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
            count = static_cast<std::size_t>(Count);
        s.lists.add([kept = std::make_tuple(glcalls::Kept<Args>(args, count)...)] {
            std::apply([](const auto&... k) { Implementation(k.get()...); }, kept);
        });
    }
};

// The functions of the list, as types: gl::glEnable (glad's macro makes it gl::glad_glEnable).
namespace gl = glcalls::call;

// The entry point of the list's function `Call` (gl::NAME), which `Implementation` implements
// with glad's signature for it.
template <class Call, auto Implementation>
EntryPoint listed() {
    static_assert(std::is_same_v<decltype(Implementation), typename Call::Signature>,
                  "the implementation's signature is not glad's for this function");
    if constexpr (Call::kClass == glcalls::ListClass::compiled)
        return {Call::kName, entry(&Compiled<Implementation, Call::kCount>::call)};
    else
        return {Call::kName, entry(Implementation)};
}

// The 2, 3 and 4 component forms of a position call (glVertex, glRasterPos) in type T and their
// vector forms, each calling `function(const T* components, int count)`.
// clang-format off
#define MYGL_POSITION_ENTRIES(name, suffix, T, function)                                                          \
    listed<gl::name##2##suffix, +[](T x, T y) { function(std::array<T, 2>{x, y}.data(), 2); }>(),                 \
    listed<gl::name##3##suffix, +[](T x, T y, T z) { function(std::array<T, 3>{x, y, z}.data(), 3); }>(),         \
    listed<gl::name##4##suffix, +[](T x, T y, T z, T w) { function(std::array<T, 4>{x, y, z, w}.data(), 4); }>(), \
    listed<gl::name##2##suffix##v, +[](const T* v) { function(v, 2); }>(),                                        \
    listed<gl::name##3##suffix##v, +[](const T* v) { function(v, 3); }>(),                                        \
    listed<gl::name##4##suffix##v, +[](const T* v) { function(v, 4); }>()
// clang-format on

}  // namespace mygl
