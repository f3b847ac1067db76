#pragma once
// A texture's texels in lanes (fragment_stage.h's lane types): where a level lies, the words
// at texel indices and their bytes as floats. Shared by the 8-bit and the float samplers
// (fragment_texture.h, fragment_texture_float.h).
#include <cstddef>

#include "glrenderer/texture.h"

namespace glrenderer {

// A texture channel as a float channel: the byte times 1/255 in float.
template <class L>
typename L::Float unormToFloat(typename L::Int byte) {
    return L::mul(L::toFloat(byte), L::floats(1.0f / 255.0f));
}

// Byte `Shift / 8` of each word.
template <class L, int Shift>
typename L::Int channel(typename L::Int word) {
    if constexpr (Shift == 24)
        return L::template shiftRightUnsigned<24>(word);
    else
        return L::bitAnd(L::template shiftRightUnsigned<Shift>(word), L::ints(0xFF));
}

// The four channels of texel words as floats in [0, 1].
template <class L>
void wordToFloats(typename L::Int word, typename L::Float out[4]) {
    out[0] = unormToFloat<L>(channel<L, 0>(word));
    out[1] = unormToFloat<L>(channel<L, 8>(word));
    out[2] = unormToFloat<L>(channel<L, 16>(word));
    out[3] = unormToFloat<L>(channel<L, 24>(word));
}

// The texel index of coordinate c under NEAREST: floor(c * size), wrapped (GL_CLAMP as
// CLAMP_TO_EDGE). REPEAT masks the index when level 0's side is a power of two (`pot`, the
// reference's static pot_width and pot_height).
template <class L>
typename L::Int nearestIndex(TextureWrap wrap, typename L::Float c, typename L::Int size, bool pot) {
    const typename L::Float sizeF = L::toFloat(size);
    const typename L::Int last = L::sub(size, L::ints(1));
    if (wrap == TextureWrap::Repeat && !pot) {
        // fract, kept below one, times the size, truncated.
        const typename L::Float f = L::min(L::sub(c, L::floor(c)), L::floats(0x1.fffffep-1f));
        return L::truncateToInt(L::mul(f, sizeF));
    }
    const typename L::Int i = L::roundToInt(L::floor(L::mul(c, sizeF)));
    if (wrap == TextureWrap::Repeat) return L::bitAnd(i, last);
    return L::minInt(L::maxInt(i, L::ints(0)), last);
}

// One mipmap level's size and place for each lane.
template <class L>
struct LevelLanes {
    typename L::Int width, height, offset;

    static LevelLanes of(const Texture& texture, int index) {
        const auto i = static_cast<std::size_t>(index);
        return {L::ints(static_cast<int>(texture.width[i])), L::ints(static_cast<int>(texture.height[i])),
                L::ints(static_cast<int>(texture.offset[i]))};
    }
    // Level `index` of each lane (clamped to the texture's levels: every lane, live or not).
    static LevelLanes of(const Texture& texture, typename L::Int index) {
        static_assert(Texture::kMaxLevels == 16);
        return {L::lookup16(texture.width.data(), index), L::lookup16(texture.height.data(), index),
                L::lookup16(texture.offset.data(), index)};
    }

    // The texel words at column i, row j (both inside the level).
    typename L::Int fetch(const Texture& texture, typename L::Int i, typename L::Int j, typename L::Mask live) const {
        return L::gather(texture.texels.data(), L::add(offset, L::add(L::mul(j, width), i)), live);
    }
};

}  // namespace glrenderer
