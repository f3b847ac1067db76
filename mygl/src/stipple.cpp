// glLineStipple, glPolygonStipple, glGetPolygonStipple and the GL_LINE_STIPPLE and
// GL_POLYGON_STIPPLE enables (issue 16).
#include <algorithm>

#include "compiled.h"
#include "pixel_store.h"
#include "stipple_state.h"

namespace mygl {
namespace {

using glrenderer::PolygonStipplePattern;

void lineStipple(GLint factor, GLushort pattern) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    glrenderer::LineStipple& l = s->draw.edit().lineStipple;
    const auto clamped = static_cast<std::uint16_t>(std::clamp(factor, 1, 256));  // GL clamps, no error
    if (l.factor != clamped || l.pattern != pattern) endBatch(*s);
    l.factor = clamped;
    l.pattern = pattern;
}

// Where bit `pixel` of row `row` of a 32 x 32 bitmap lies in client memory under `modes`.
struct BitPlace {
    std::size_t byte;
    unsigned mask;
};
BitPlace bitPlace(const PixelStoreModes& modes, int row, int pixel) {
    const ClientLayout layout = clientLayout(32, GL_COLOR_INDEX, GL_BITMAP, modes);
    const std::size_t bit = layout.firstBit + static_cast<std::size_t>(pixel);
    const unsigned inByte = static_cast<unsigned>(bit % 8);
    return {layout.firstByte + static_cast<std::size_t>(row) * layout.rowStride + bit / 8,
            modes.lsbFirst ? 1u << inByte : 0x80u >> inByte};
}

// Row i of the pattern holds window row i, its pixel x in bit 31 - x.
PolygonStipplePattern unpackStipple(const GLubyte* mask, const PixelStoreModes& modes) {
    PolygonStipplePattern pattern{};
    for (int row = 0; row < 32; ++row) {
        for (int x = 0; x < 32; ++x) {
            const BitPlace place = bitPlace(modes, row, x);
            if (mask[place.byte] & place.mask) pattern[static_cast<std::size_t>(row)] |= 0x80000000u >> x;
        }
    }
    return pattern;
}

void setPolygonStipple(const PolygonStipplePattern& pattern) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const PolygonStipplePattern* interned = glrenderer::internPolygonStipple(pattern);
    if (s->draw->polygonStipple.pattern != interned) endBatch(*s);
    s->draw.edit().polygonStipple.pattern = interned;
}

// glPolygonStipple: unpacked under the unpack modes of the call, also when a list compiles it
// (the list keeps the pattern). A null mask changes nothing, as in the reference.
void polygonStipple(const GLubyte* mask) {
    Context::State* s = currentState();
    if (!s || !mask) return;
    const PolygonStipplePattern pattern = unpackStipple(mask, s->unpack);
    if (s->lists.compiling()) {
        s->lists.add([pattern] { setPolygonStipple(pattern); });
        if (!s->lists.executingWhileCompiling()) return;
    }
    setPolygonStipple(pattern);
}

// glGetPolygonStipple packs as the reference does: each byte a row reaches is cleared before its
// bits are set, the skipped bits of the first byte too.
void getPolygonStipple(GLubyte* mask) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !mask) return;
    const PolygonStipplePattern* pattern = s->draw->polygonStipple.pattern;
    const unsigned firstInByte = s->pack.lsbFirst ? 1u : 0x80u;
    for (int row = 0; row < 32; ++row) {
        const std::uint32_t bits = pattern ? (*pattern)[static_cast<std::size_t>(row)] : 0xFFFFFFFFu;
        for (int x = 0; x < 32; ++x) {
            const BitPlace place = bitPlace(s->pack, row, x);
            if (x == 0 || place.mask == firstInByte) mask[place.byte] = 0;
            if (bits & (0x80000000u >> x)) mask[place.byte] = static_cast<GLubyte>(mask[place.byte] | place.mask);
        }
    }
}

template <class DrawState>
auto* enableOf(DrawState& draw, GLenum cap) {
    using Flag = decltype(&draw.lineStipple.enabled);
    switch (cap) {
    case GL_LINE_STIPPLE: return &draw.lineStipple.enabled;
    case GL_POLYGON_STIPPLE: return &draw.polygonStipple.enabled;
    default: return Flag{nullptr};
    }
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glLineStipple, +[](GLint factor, GLushort pattern) { lineStipple(factor, pattern); }>(),
    listed<gl::glPolygonStipple, +[](const GLubyte* mask) { polygonStipple(mask); }>(),
    listed<gl::glGetPolygonStipple, +[](GLubyte* mask) { getPolygonStipple(mask); }>(),
};

}  // namespace

bool setStippleCapability(Context::State& state, GLenum cap, bool enabled) {
    bool* flag = enableOf(state.draw.edit(), cap);
    if (!flag) return false;
    if (*flag != enabled) endBatch(state);
    *flag = enabled;
    return true;
}

std::optional<bool> stippleCapability(const Context::State& state, GLenum cap) {
    const bool* flag = enableOf(*state.draw, cap);
    return flag ? std::optional<bool>(*flag) : std::nullopt;
}

std::span<const EntryPoint> stippleEntryPoints() { return kEntryPoints; }

}  // namespace mygl
