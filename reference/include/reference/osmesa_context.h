#pragma once
#include <cstdint>
#include <vector>

namespace reference {

using ProcAddress = void (*)();

// An OSMesa context (RGBA8, 24-bit depth) with its own buffer. All GL calls reach it through the
// GL loader table (<glad/gl.h>) filled from OSMesaGetProcAddress, never through a linked symbol.
class OsmesaContext {
public:
    // Throws std::runtime_error if OSMesa cannot create the context or the size is not positive.
    OsmesaContext(int width, int height);
    ~OsmesaContext();
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    // Makes the context current and loads the GL table with OSMesa's entry points.
    void makeCurrent();

    // A new buffer of this size for the same context (GL state kept), bound at once; its
    // contents are undefined until drawn. Throws std::runtime_error if the size is not positive.
    void resize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }

    // glFinish, then the buffer as RGBA8, bottom row first.
    std::vector<std::uint8_t> readPixels();

    // OSMesa's entry point for `name` (any GL version it offers, e.g. occlusion queries).
    static ProcAddress getProcAddress(const char* name);

private:
    struct Handle;
    Handle* handle_ = nullptr;
    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint8_t> buffer_;
};

}  // namespace reference
