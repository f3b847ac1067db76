// glReadPixels: the part of a rectangle inside the window, read after everything queued is
// drawn, packed under the pack state; the caller's memory for the rest is left untouched.
#include "read_pixels.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "compiled.h"
#include "framebuffer_pack.h"

namespace mygl {
namespace {

// The part of [start, start + length) inside [0, limit), as an offset into the range and a
// count; computed in 64 bits, so no start or length overflows.
struct Span {
    std::int64_t offset = 0, count = 0;
};
Span clipToWindow(GLint start, GLsizei length, int limit) {
    const std::int64_t first = std::max<std::int64_t>(start, 0);
    const std::int64_t last = std::min<std::int64_t>(std::int64_t{start} + length, limit);
    return last > first ? Span{first - start, last - first} : Span{};
}

bool isColorFormat(GLenum format) {
    return isPixelFormat(format) && format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX &&
           format != GL_DEPTH_COMPONENT;
}

// The window's words (colour or depth) inside the clipped rectangle, bottom row first.
std::vector<std::uint32_t> wordsInside(const std::uint32_t* window, int windowWidth, std::int64_t x, std::int64_t y,
                                       const Span& columns, const Span& rows) {
    std::vector<std::uint32_t> words(static_cast<std::size_t>(columns.count * rows.count));
    for (std::int64_t row = 0; row < rows.count; ++row) {
        const std::int64_t windowRow = y + rows.offset + row;
        const std::uint32_t* source = window + windowRow * windowWidth + x + columns.offset;
        std::copy_n(source, columns.count, words.begin() + row * columns.count);
    }
    return words;
}

}  // namespace

void readPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, void* pixels) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    // The reference checks the size before the format and type.
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    s->updateModelviewProjection();  // the reference validates its state here
    if (!isPixelFormat(format)) return setError(*s, GL_INVALID_ENUM);
    const bool indexFormat = format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX;
    if (!isPixelType(type) || (type == GL_BITMAP && !indexFormat)) return setError(*s, GL_INVALID_ENUM);
    // An RGBA buffer has no colour indices; stencil is read as integers or floats.
    if (format == GL_COLOR_INDEX || type == GL_BITMAP) return setError(*s, GL_INVALID_OPERATION);
    if (!pixels) return;
    drawCachedBitmaps(*s);
    s->pipeline.finish();
    const auto& fb = s->framebuffer;
    const Span columns = clipToWindow(x, width, fb.width()), rows = clipToWindow(y, height, fb.height());
    if (columns.count == 0 || rows.count == 0) return;
    const PackTarget target{pixels, width, static_cast<std::size_t>(columns.offset),
                            static_cast<std::size_t>(rows.offset)};
    const int w = static_cast<int>(columns.count), h = static_cast<int>(rows.count);
    if (format == GL_STENCIL_INDEX) {
        const auto values = wordsInside(fb.stencil().data(), fb.width(), x, y, columns, rows);
        return packStencils(values, w, h, type, s->pack, s->pixelModes, s->pixelMaps, target);
    }
    if (format == GL_DEPTH_COMPONENT) {
        const auto depths = wordsInside(fb.depth().data(), fb.width(), x, y, columns, rows);
        return packDepths(depths, w, h, type, s->pack, s->pixelModes, target);
    }
    if (isColorFormat(format)) {
        const auto colors = wordsInside(fb.color().data(), fb.width(), x, y, columns, rows);
        packColors(colors, w, h, format, type, s->pack, s->pixelModes, s->pixelMaps, target);
    }
}

}  // namespace mygl
