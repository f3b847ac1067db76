#include "not_implemented.h"

#include <glcalls/gl11_calls.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <string_view>
#include <type_traits>

namespace mygl {

void reportNotImplemented(const char* name) {
    if (Context::State* s = currentState()) setError(*s, GL_INVALID_OPERATION);
    static std::mutex mutex;
    static std::set<std::string_view> reported;
    const std::lock_guard lock(mutex);
    if (reported.insert(name).second) {
        std::fprintf(stderr, "MyGL: %s is not implemented yet (GL_INVALID_OPERATION)\n", name);
    }
}

namespace {

// A name as a template argument, so that each stub knows its function.
template <std::size_t N>
struct FunctionName {
    constexpr FunctionName(const char (&text)[N]) { std::copy_n(text, N, chars); }
    char chars[N];
};

// The stub for `Name`, with the exact signature of glad's function pointer type.
template <FunctionName Name, class Pointer>
struct Stub;
template <FunctionName Name, class R, class... Args>
struct Stub<Name, R(GLAD_API_PTR*)(Args...)> {
    static R GLAD_API_PTR call(Args...) {
        reportNotImplemented(Name.chars);
        if constexpr (!std::is_void_v<R>) return R{};
    }
};

}  // namespace

std::vector<EntryPoint> notImplementedEntryPoints(std::span<const EntryPoint> implemented) {
    static const EntryPoint kAll[] = {
#define MYGL_STUB(name, class_, count) {#name, entry(&Stub<#name, decltype(glad_##name)>::call)},
        MYGL_GL11_CALLS(MYGL_STUB)
#undef MYGL_STUB
    };
    const auto byName = [](const EntryPoint& a, const EntryPoint& b) { return std::strcmp(a.name, b.name) < 0; };
    std::vector<EntryPoint> missing;
    std::set_difference(std::begin(kAll), std::end(kAll), implemented.begin(), implemented.end(),
                        std::back_inserter(missing), byName);
    return missing;
}

}  // namespace mygl
