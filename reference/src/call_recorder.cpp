#include "reference/call_recorder.h"
#include "reference/recorded_calls.h"

#include <glad/gl.h>

#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

namespace reference {
namespace {

CallRecorder* active = nullptr;

// An argument kept for replay: values as they are, and for a pointer to const data the `count`
// elements behind it (the pointer the program passed may not outlive the call).
template <class T>
struct Kept {
    T value;
    Kept(T v, std::size_t) : value(v) {}
    T get() const { return value; }
};
template <class T>
struct Kept<const T*> {
    std::vector<T> data;
    bool null;
    Kept(const T* p, std::size_t count) : data(p ? std::vector<T>(p, p + count) : std::vector<T>()), null(!p) {}
    const T* get() const { return null ? nullptr : data.data(); }
};

// The wrapper for the table entry `Slot`: records the call, then forwards it to the backend
// the table pointed at when recording started. `Count` is how many elements a pointer argument
// points at. Replay calls through `Slot`, i.e. through whatever table is loaded then.
template <auto& Slot, std::size_t Count, class Signature = std::remove_reference_t<decltype(Slot)>>
struct Wrapper;

template <auto& Slot, std::size_t Count, class R, class... Args>
struct Wrapper<Slot, Count, R(GLAD_API_PTR*)(Args...)> {
    static inline R(GLAD_API_PTR* original)(Args...) = nullptr;

    static R GLAD_API_PTR call(Args... args) {
        if (active) {
            active->add([kept = std::make_tuple(Kept<Args>(args, Count)...)] {
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

void installAll() {
#define MYGL_INSTALL(slot, count) Wrapper<slot, count>::install();
    MYGL_RECORDED_CALLS(MYGL_INSTALL)
#undef MYGL_INSTALL
}

void uninstallAll() {
#define MYGL_UNINSTALL(slot, count) Wrapper<slot, count>::uninstall();
    MYGL_RECORDED_CALLS(MYGL_UNINSTALL)
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
