#include "reference/call_recorder.h"

#include <glad/gl.h>
#include <glcalls/gl11_calls.h>
#include <glcalls/kept_argument.h>

#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

namespace reference {
namespace {

CallRecorder* active = nullptr;

// How many elements a pointer argument of the call points at, by its count rule (gl11_calls.h):
// a number, or a function of the call's arguments, or of the unpack modes too (asked of the
// backend: queries, not recorded).
template <auto Count, class... Args>
std::size_t elementCount(Args... args) {
    if constexpr (std::is_invocable_v<decltype(Count), Args...>) {
        return Count(args...);
    } else if constexpr (std::is_invocable_v<decltype(Count), const glcalls::UnpackModes&, Args...>) {
        glcalls::UnpackModes unpack;
        if (glad_glGetIntegerv) {
            glad_glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpack.alignment);
            glad_glGetIntegerv(GL_UNPACK_ROW_LENGTH, &unpack.rowLength);
            glad_glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &unpack.skipPixels);
            glad_glGetIntegerv(GL_UNPACK_SKIP_ROWS, &unpack.skipRows);
        }
        return Count(unpack, args...);
    } else {
        return static_cast<std::size_t>(Count);
    }
}

// The wrapper for the table entry `Slot`: records the call, then forwards it to the backend
// the table pointed at when recording started. `Count` says how many elements a pointer
// argument points at (elementCount). Replay calls through `Slot`, i.e. through whatever table
// is loaded then.
template <auto& Slot, auto Count, class Signature = std::remove_reference_t<decltype(Slot)>>
struct Wrapper;

template <auto& Slot, auto Count, class R, class... Args>
struct Wrapper<Slot, Count, R(GLAD_API_PTR*)(Args...)> {
    static inline R(GLAD_API_PTR* original)(Args...) = nullptr;

    static R GLAD_API_PTR call(Args... args) {
        if (active) {
            [[maybe_unused]] const std::size_t count = elementCount<Count>(args...);
            active->add([kept = std::make_tuple(glcalls::Kept<Args>(args, count)...)] {
                std::apply([](const auto&... k) { Slot(k.get()...); }, kept);
            });
        }
        return original(args...);
    }
    static void install() {
        original = Slot;
        if (original) Slot = &call;
    }
    static void uninstall() {
        if (original) Slot = original;
    }
};

// Every function of the list that is not a query: what changes GL state or draws.
void installAll() {
#define MYGL_INSTALL(name, class_, count)                                  \
    if constexpr (glcalls::ListClass::class_ != glcalls::ListClass::query) \
        Wrapper<glad_##name, glcalls::call::name::kCount>::install();
    MYGL_GL11_CALLS(MYGL_INSTALL)
#undef MYGL_INSTALL
}

void uninstallAll() {
#define MYGL_UNINSTALL(name, class_, count)                                \
    if constexpr (glcalls::ListClass::class_ != glcalls::ListClass::query) \
        Wrapper<glad_##name, glcalls::call::name::kCount>::uninstall();
    MYGL_GL11_CALLS(MYGL_UNINSTALL)
#undef MYGL_UNINSTALL
}

}  // namespace

CallRecorder::~CallRecorder() { stop(); }

void CallRecorder::start() {
    if (recording_) return;
    if (active) throw std::logic_error("another CallRecorder is recording");
    active = this;
    recording_ = true;
    installAll();
}

void CallRecorder::stop() {
    if (!recording_) return;
    uninstallAll();
    active = nullptr;
    recording_ = false;
}

void CallRecorder::replay() const {
    if (recording_) throw std::logic_error("stop recording before replaying");
    for (const auto& call : calls_) call();
}

}  // namespace reference
