#include "glrenderer/accumulation.h"

#include <algorithm>
#include <cstdint>

#include "glrenderer/color_convert.h"

namespace glrenderer {
namespace {

// C's (short)(float) as the reference's compiler does it on x86-64: truncation to a 32-bit
// integer (cvttss2si, whose out-of-range and NaN answer is 0x80000000), then its low 16 bits.
std::int16_t toWord(float value) {
    const bool inRange = value >= -2147483648.0f && value < 2147483648.0f;
    const auto wide = inRange ? static_cast<std::int32_t>(value) : INT32_MIN;
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(static_cast<std::uint32_t>(wide) & 0xFFFFu));
}

// A 16-bit sum that wraps, as the reference's `acc[i] += x` on shorts.
std::int16_t wrappingAdd(std::int16_t a, std::int16_t b) {
    return static_cast<std::int16_t>(
        static_cast<std::uint16_t>(static_cast<std::uint16_t>(a) + static_cast<std::uint16_t>(b)));
}

// GL's float to signed 16-bit for the clear value (Mesa's FLOAT_TO_SHORT).
std::int16_t clearWord(float value) {
    return static_cast<std::int16_t>((static_cast<std::int32_t>(65535.0f * value) - 1) / 2);
}

std::uint8_t channel(std::uint32_t rgba, int c) { return static_cast<std::uint8_t>(rgba >> (8 * c)); }

// Calls `visit(pixelIndex)` for every pixel of the framebuffer, inside the scissor box when it
// is enabled.
template <class Visit>
void forEachPixel(const Framebuffer& fb, const ScissorBox& scissor, Visit&& visit) {
    int x0 = 0, x1 = fb.width(), y0 = 0, y1 = fb.height();
    if (scissor.enabled) {  // in 64 bits: x + width may pass INT_MAX
        x0 = static_cast<int>(std::clamp<std::int64_t>(scissor.x, 0, x1));
        y0 = static_cast<int>(std::clamp<std::int64_t>(scissor.y, 0, y1));
        x1 = static_cast<int>(std::clamp<std::int64_t>(std::int64_t{scissor.x} + scissor.width, x0, x1));
        y1 = static_cast<int>(std::clamp<std::int64_t>(std::int64_t{scissor.y} + scissor.height, y0, y1));
    }
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x)
            visit(static_cast<std::size_t>(y) * static_cast<std::size_t>(fb.width()) + static_cast<std::size_t>(x));
    }
}

}  // namespace

void clearAccum(Framebuffer& fb, const ScissorBox& scissor, const std::array<float, 4>& value) {
    const std::array<std::int16_t, 4> words{clearWord(value[0]), clearWord(value[1]), clearWord(value[2]),
                                            clearWord(value[3])};
    const std::span<std::int16_t> accum = fb.accum();
    forEachPixel(fb, scissor, [&](std::size_t i) {
        std::copy(words.begin(), words.end(), accum.begin() + static_cast<std::ptrdiff_t>(4 * i));
    });
}

void accumulate(Framebuffer& fb, const ScissorBox& scissor, std::uint32_t colorMask, AccumOp op, float value) {
    const std::span<std::int16_t> accum = fb.accum();
    const std::span<std::uint32_t> color = fb.color();
    // The colour buffer's bytes as the reference unpacks them (x / 255), scaled to the words' range.
    const float scale = value * 32767.0f;
    switch (op) {
    case AccumOp::Load:
        forEachPixel(fb, scissor, [&](std::size_t i) {
            for (int c = 0; c < 4; ++c)
                accum[4 * i + c] = toWord(static_cast<float>(channel(color[i], c)) / 255.0f * scale);
        });
        break;
    case AccumOp::Accum:
        forEachPixel(fb, scissor, [&](std::size_t i) {
            for (int c = 0; c < 4; ++c) {
                std::int16_t& word = accum[4 * i + c];
                word = wrappingAdd(word, toWord(static_cast<float>(channel(color[i], c)) / 255.0f * scale));
            }
        });
        break;
    case AccumOp::Add: {
        const std::int16_t increment = toWord(scale);
        forEachPixel(fb, scissor, [&](std::size_t i) {
            for (int c = 0; c < 4; ++c) accum[4 * i + c] = wrappingAdd(accum[4 * i + c], increment);
        });
        break;
    }
    case AccumOp::Mult:
        forEachPixel(fb, scissor, [&](std::size_t i) {
            for (int c = 0; c < 4; ++c) accum[4 * i + c] = toWord(static_cast<float>(accum[4 * i + c]) * value);
        });
        break;
    case AccumOp::Return: {
        const float unscale = value / 32767.0f;
        forEachPixel(fb, scissor, [&](std::size_t i) {
            const std::int16_t* words = &accum[4 * i];
            const std::uint32_t rgba = packRgba8(toUnorm8(words[0] * unscale), toUnorm8(words[1] * unscale),
                                                 toUnorm8(words[2] * unscale), toUnorm8(words[3] * unscale));
            color[i] = (rgba & colorMask) | (color[i] & ~colorMask);
        });
        fb.markWritten();
        break;
    }
    }
}

}  // namespace glrenderer
