#pragma once
// glAccum and the accumulation buffer's clear, with the reference's arithmetic (Mesa's
// main/accum.c on GL_RGBA16_SNORM words; docs/reference-rules.md, "Accumulation buffer").
#include <array>

#include "glrenderer/framebuffer.h"

namespace glrenderer {

// The pixels an operation touches: the window, or less (a scissor box, once there is one).
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
};

enum class AccumOp { Accum, Load, Return, Mult, Add };

// Fills `rect` of the accumulation buffer with the clear value (each channel already clamped to
// [-1, 1]).
void clearAccum(Framebuffer& framebuffer, const PixelRect& rect, const std::array<float, 4>& value);

// One glAccum operation on `rect`; Accum and Load read the colour buffer, Return writes it
// (and marks it written). The pipeline must have drawn everything before.
void accumulate(Framebuffer& framebuffer, const PixelRect& rect, AccumOp op, float value);

}  // namespace glrenderer
