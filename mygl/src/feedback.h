#pragma once
// GL_FEEDBACK's state (glFeedbackBuffer) and the writing of its tokens (feedback.cpp).
#include <glad/gl.h>

#include <cstddef>

namespace mygl {

struct Feedback {
    GLfloat* buffer = nullptr;
    GLsizei size = 0;
    GLenum type = GL_2D;
    std::size_t count = 0;  // values written, or that would have been: more than `size` is an overflow

    void write(GLfloat value) {
        if (buffer && count < static_cast<std::size_t>(size)) buffer[count] = value;
        ++count;
    }
};

}  // namespace mygl
