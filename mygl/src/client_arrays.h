#pragma once
// The client-side vertex arrays (glVertexPointer, glColorPointer, ...) and reading their
// elements as the immediate-mode calls they stand for.
#include <glad/gl.h>

#include <cstddef>

namespace mygl {

struct ClientArray {
    bool enabled = false;
    GLint size;
    GLenum type = GL_FLOAT;
    GLsizei stride = 0;  // 0: tightly packed
    const void* pointer = nullptr;

    // Where element i starts.
    const void* element(std::size_t i) const;
};

struct ClientArrays {
    ClientArray vertex{.size = 4};
    ClientArray normal{.size = 3};
    ClientArray color{.size = 4};
    ClientArray index{.size = 1};
    ClientArray texCoord{.size = 4};
    ClientArray edgeFlag{.size = 1, .type = GL_UNSIGNED_BYTE};

    // The array `name` (GL_VERTEX_ARRAY, ...) names, or nullptr.
    ClientArray* find(GLenum name);
};

// Bytes of one component of `type` (0 for a type arrays do not take).
std::size_t componentBytes(GLenum type);

}  // namespace mygl
