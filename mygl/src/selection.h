#pragma once
// GL_SELECT's state: the program's hit buffer and the name stack.
#include <glad/gl.h>

#include <glrenderer/hit_range.h>
#include <cstddef>
#include <vector>

namespace mygl {

struct Selection {
    static constexpr std::size_t kMaxNameStackDepth = 64;  // the reference's GL_MAX_NAME_STACK_DEPTH

    Selection() { names.reserve(kMaxNameStackDepth); }

    GLuint* buffer = nullptr;  // glSelectBuffer
    GLsizei size = 0;
    std::size_t count = 0;  // values written, or that would have been: more than `size` is an overflow
    GLint hits = 0;
    std::vector<GLuint> names;
    glrenderer::HitRange rasterHits;  // of glRasterPos, which the pipeline does not see

    void write(GLuint value) {
        if (buffer && count < static_cast<std::size_t>(size)) buffer[count] = value;
        ++count;
    }
};

}  // namespace mygl
