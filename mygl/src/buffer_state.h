#pragma once
// The state of the buffers besides colour and depth: the accumulation buffer's clear value, the
// colour buffers drawn and read (glDrawBuffer, glReadBuffer), and the colour-index state an RGBA
// context keeps for glGet without using it.
#include <glad/gl.h>

#include <glrenderer/accumulation.h>
#include <array>

namespace mygl {

struct BufferState {
    std::array<float, 4> accumClear{};  // glClearAccum, clamped to [-1, 1]
    GLenum drawBuffer = GL_FRONT, readBuffer = GL_FRONT;
    float currentIndex = 1.0f;  // glIndex
    GLuint clearIndex = 0;      // glClearIndex, truncated as the reference stores it
    GLuint indexMask = ~0u;     // glIndexMask
};

}  // namespace mygl
