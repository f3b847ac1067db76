#pragma once
// glAccum and the accumulation buffer's clear, with the reference's arithmetic (Mesa's
// main/accum.c on GL_RGBA16_SNORM words; docs/reference-rules.md, "Accumulation buffer").
#include <array>

#include "glrenderer/fragment_ops.h"
#include "glrenderer/framebuffer.h"

namespace glrenderer {

enum class AccumOp { Accum, Load, Return, Mult, Add };

// Both touch the window's pixels, inside the scissor box when it is enabled.
// Fills the accumulation buffer with the clear value (each channel already clamped to [-1, 1]).
void clearAccum(Framebuffer& framebuffer, const ScissorBox& scissor, const std::array<float, 4>& value);

// One glAccum operation; Accum and Load read the colour buffer, Return writes the bits of
// `colorMask` (FragmentOps::colorMask) and marks it written. The pipeline must have drawn
// everything before.
void accumulate(Framebuffer& framebuffer, const ScissorBox& scissor, std::uint32_t colorMask, AccumOp op, float value);

}  // namespace glrenderer
