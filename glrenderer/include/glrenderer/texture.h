#pragma once
// Textures as the pipeline samples them: immutable images (a queued batch keeps the one it
// read alive through its DrawState) and the state that says how to sample and combine them.
#include <array>
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
// The mipmap filter of the minification filter: None for GL_NEAREST and GL_LINEAR.
enum class MipmapFilter : std::uint8_t { None, Nearest, Linear };
// GL_CLAMP under NEAREST filters samples as GL_CLAMP_TO_EDGE (its border is never reached);
// Clamp is GL_CLAMP where a filter is LINEAR (or the mipmap filter): the reference samples it
// in float, the border colour beyond the edges (fragment_texture_float.h).
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, Clamp };
// What the texels of a draw's texture give its fragments: colours for the environment, or
// (the images of glDrawPixels and glCopyPixels of depth and stencil) each fragment's 24-bit
// window depth or its stencil value, the texel word itself, sampled nearest.
enum class TexelUse : std::uint8_t { Color, Depth, Stencil };

// A texture's images (its mipmap levels, or level 0 alone), their texels expanded to RGBA8
// words (R in the low byte) as the reference's 8-bit sampler sees them: luminance L as
// (L, L, L, 1), intensity I as (I, I, I, I), alpha A as (0, 0, 0, A), RGB as (R, G, B, 1).
// All levels lie in one array, so that lanes on different levels gather from one base.
struct Texture {
    static constexpr int kMaxLevels = 16;
    int levelCount = 0;
    // Per level, as 32-bit words for the lanes' gathers: width, height (1 for a 1D texture)
    // and the index of its first texel in `texels`.
    std::array<std::uint32_t, kMaxLevels> width{}, height{}, offset{};
    bool powerOfTwoWidth = true, powerOfTwoHeight = true;  // level 0's
    std::vector<std::uint32_t> texels;
};

// glTexGen: which of S, T, R, Q (bits 0-3) are generated, and how.
enum class TexGenMode : std::uint8_t { ObjectLinear, EyeLinear, SphereMap };
struct TextureGen {
    std::uint8_t enabled = 0;
    std::array<TexGenMode, 4> mode{TexGenMode::EyeLinear, TexGenMode::EyeLinear, TexGenMode::EyeLinear,
                                   TexGenMode::EyeLinear};
    std::array<glm::vec4, 4> objectPlane{}, eyePlane{};  // eye planes as stored: times the inverse modelview
    // For SPHERE_MAP: the inverse modelview (eye normals) and whether normals are normalized.
    Matrix inverseModelview = kIdentity;
    bool normalize = false;
    bool operator==(const TextureGen&) const = default;
};

// What a draw samples and how; the image is shared, never changed once made.
struct TextureState {
    TextureEnv env = TextureEnv::Off;
    bool oneDimensional = false;  // GL_TEXTURE_1D
    TextureBase base = TextureBase::Rgba;
    TextureFilter minFilter = TextureFilter::Nearest, magFilter = TextureFilter::Nearest;
    MipmapFilter mipFilter = MipmapFilter::None;
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    TexelUse use = TexelUse::Color;
    glm::vec4 envColor{0.0f};  // GL_TEXTURE_ENV_COLOR, clamped
    // GL_TEXTURE_BORDER_COLOR as a Clamp wrap samples it: clamped, then taken as the base
    // format takes a colour (luminance (R, R, R, 1), ...); zero without a Clamp wrap.
    glm::vec4 borderColor{0.0f};
    TextureGen gen;
    Matrix matrix = kIdentity;  // the texture matrix
    bool identityMatrix = true;
    std::shared_ptr<const Texture> texture;
    bool operator==(const TextureState&) const = default;
};

}  // namespace glrenderer
