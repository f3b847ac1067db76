#pragma once
#include <glad/gl.h>

namespace mygl {

// glReadPixels.
void readPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void* pixels);

}  // namespace mygl
