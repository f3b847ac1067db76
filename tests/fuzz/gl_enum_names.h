#pragma once
// GL enum values back to their names, for printing call streams as C.
#include <glad/gl.h>

#include <string>

namespace fuzz {

// "GL_TRIANGLES" for a glBegin mode, else "" (modes share their values with other enums).
std::string primitiveModeName(GLenum mode);
// "GL_CULL_FACE" for an enum the fuzzer generates (values from 0x100 up are unique), else "".
std::string enumName(GLenum value);
// "GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT", with unknown bits in hexadecimal.
std::string clearMaskName(GLbitfield mask);

}  // namespace fuzz
