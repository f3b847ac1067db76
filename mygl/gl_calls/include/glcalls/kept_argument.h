#pragma once
// An argument of a GL call kept to be made again later (a display list's call in MyGL, a call
// the reference's CallRecorder replays): a value as it is; for a pointer to const data, the
// `count` elements behind it, since the program's memory may change or be gone by then. `count`
// comes from the call's count rule in gl11_calls.h.
#include <glad/gl.h>

#include <cstddef>
#include <vector>

namespace glcalls {

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

// Untyped data: the `bytes` behind it are copied; with none, the pointer itself is kept (vertex
// array pointers, which a replayed glDrawArrays reads then).
template <>
struct Kept<const void*> {
    std::vector<unsigned char> data;
    const void* pointer;
    Kept(const void* p, std::size_t bytes)
        : data(p && bytes ? std::vector<unsigned char>(static_cast<const unsigned char*>(p),
                                                       static_cast<const unsigned char*>(p) + bytes)
                          : std::vector<unsigned char>()),
          pointer(p) {}
    const void* get() const { return data.empty() ? pointer : data.data(); }
};

// Names the call writes. With a count (glGenTextures) the replay writes storage of its own, as the
// program's array may be gone by then; without one (glSelectBuffer's hit buffer) the program's
// pointer is kept.
template <>
struct Kept<GLuint*> {
    GLuint* pointer;
    mutable std::vector<GLuint> names;
    Kept(GLuint* p, std::size_t count) : pointer(p), names(count) {}
    GLuint* get() const { return names.empty() ? pointer : names.data(); }
};

}  // namespace glcalls
