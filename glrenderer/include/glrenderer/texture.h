#pragma once
// Textures as the pipeline samples them: immutable images (a queued batch keeps the one it
// read alive through its DrawState) and the state that says how to sample and combine them.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "glrenderer/matrix.h"

namespace glrenderer {

// glTexEnv's modes; Off when no texture target is enabled (or its texture is incomplete).
enum class TextureEnv : std::uint8_t { Off, Modulate, Replace, Decal, Blend, Add };
// Which of R, G, B, A a texture's internal format holds: what the environment takes from it.
enum class TextureBase : std::uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, Rgb, Rgba };
enum class TextureFilter : std::uint8_t { Nearest, Linear };
// GL_CLAMP samples as GL_CLAMP_TO_EDGE under NEAREST (its border is never reached).
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge };

// One texture image, its texels expanded to RGBA8 words (R in the low byte) as the reference's
// 8-bit sampler sees them: luminance L as (L, L, L, 1), intensity I as (I, I, I, I), alpha A
// as (0, 0, 0, A), RGB as (R, G, B, 1).
struct TextureImage {
    int width = 0, height = 0;  // height 1 for a 1D texture
    std::vector<std::uint32_t> texels;
};

// What a draw samples and how; the image is shared, never changed once made.
struct TextureState {
    TextureEnv env = TextureEnv::Off;
    TextureBase base = TextureBase::Rgba;
    TextureFilter filter = TextureFilter::Nearest;
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    glm::vec4 envColor{0.0f};  // GL_TEXTURE_ENV_COLOR, clamped
    Matrix matrix = kIdentity;  // the texture matrix
    bool identityMatrix = true;
    std::shared_ptr<const TextureImage> image;
    bool operator==(const TextureState&) const = default;
};

}  // namespace glrenderer
