// glClear's writes: whole buffers tile by tile at the next flush, the rest at once (issue 16:
// scissor, colour mask, depth mask, stencil).
#include <cstddef>
#include <cstdint>
#include <span>

#include "batch_drawer.h"
#include "glrenderer/invariant.h"
#include "glrenderer/pipeline.h"
#include "pixel_rect.h"

namespace glrenderer {

void Pipeline::clear(const ClearRequest& request) {
    buffer_.flushAndReset();
    drawSubmitted();
    Framebuffer& fb = drawer_->framebuffer();
    const PixelRect rect = drawableRect(request.scissor, fb.width(), fb.height());
    if (rect.minX > rect.maxX || rect.minY > rect.maxY) return;
    MYGL_INVARIANT(rect.minX >= 0 && rect.minY >= 0 && rect.maxX < fb.width() && rect.maxY < fb.height());
    const bool whole = rect.minX == 0 && rect.minY == 0 && rect.maxX == fb.width() - 1 && rect.maxY == fb.height() - 1;
    const bool wholeColor = request.color && whole && request.colorMask == 0xFFFFFFFFu;
    const bool wholeDepth = request.depth && whole;
    if (wholeColor || wholeDepth) drawer_->clearAtFlush(wholeColor, request.rgba, wholeDepth, request.depth24);
    const bool partColor = request.color && !wholeColor && request.colorMask != 0;
    const bool partDepth = request.depth && !wholeDepth;
    const bool stencil = request.stencil && request.stencilMask != 0;
    if (!partColor && !partDepth && !stencil) return;
    if (partColor || partDepth) drawer_->flush();  // a pending clear first
    // Each buffer's bits under its mask take the value's.
    const auto fill = [&](std::span<std::uint32_t> pixels, std::uint32_t value, std::uint32_t mask) {
        for (int row = rect.minY; row <= rect.maxY; ++row) {
            const std::size_t first =
                static_cast<std::size_t>(fb.height() - 1 - row) * static_cast<std::size_t>(fb.width());
            for (int x = rect.minX; x <= rect.maxX; ++x) {
                std::uint32_t& pixel = pixels[first + static_cast<std::size_t>(x)];
                pixel = (pixel & ~mask) | (value & mask);
            }
        }
    };
    if (partColor) fill(fb.color(), request.rgba, request.colorMask);
    if (partDepth) fill(fb.depth(), request.depth24, 0xFFFFFFFFu);
    if (stencil) fill(fb.stencil(), request.stencilValue, request.stencilMask);
    if (partColor || partDepth) fb.markWritten();
}

}  // namespace glrenderer
