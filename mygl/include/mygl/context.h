#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glrenderer/methods.h>
#include <glrenderer/stats.h>

namespace mygl {

using Stats = glrenderer::Stats;
using ProcAddress = void (*)();

// Our implementation of the GL entry point `name` ("glBegin", ...), or nullptr if MyGL has none.
// Pass it to the GL loader: gladLoadGL(reinterpret_cast<GLADloadfunc>(mygl::getProcAddress)).
ProcAddress getProcAddress(const char* name);
// Whether MyGL implements `name`; getProcAddress also answers for the GL 1.1 functions it does
// not implement yet, with an entry point that reports itself (GL_INVALID_OPERATION).
bool implements(const char* name);

// A software GL context rendering into its own RGBA8 + 24-bit depth buffer.
class Context {
public:
    static constexpr int kMaxSize = 16384;

    // Throws std::invalid_argument unless 1 <= width, height <= kMaxSize.
    Context(int width, int height);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Routes gl* calls to this context and loads the GL table (<glad/gl.h>) with our entry points.
    void makeCurrent();
    static Context* current();

    // Resizes the buffers (contents undefined until cleared); the viewport is left alone, as GL does.
    void resize(int width, int height);
    int width() const;
    int height() const;

    // glFinish, then the color buffer as RGBA8, bottom row first (the OSMesa buffer's layout).
    std::vector<std::uint8_t> readPixels();

    // How triangles become pixels (default: the exact method, perspective-correct colors).
    void setMethods(const glrenderer::Methods& methods);

    // Counters since the last glClear of the color buffer (or resetStats()); finishes the frame.
    Stats stats();
    void resetStats();

    struct State;  // the GL state machine; defined in mygl/src
    State& state() { return *state_; }

private:
    std::unique_ptr<State> state_;
};

}  // namespace mygl
