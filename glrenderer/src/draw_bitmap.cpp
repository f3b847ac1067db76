// glBitmap's fragments: written straight into the framebuffer once everything queued before
// them is drawn, as the reference draws a bitmap after flushing its own vertex buffer.
#include <algorithm>

#include "batch_drawer.h"
#include "depth_test.h"
#include "glrenderer/color_convert.h"
#include "glrenderer/pipeline.h"

namespace glrenderer {

void Pipeline::drawBitmap(const DrawState& state, const Bitmap& bitmap) {
    finish();
    Framebuffer& fb = drawer_->framebuffer();
    // In 64 bits: a bitmap may start anywhere an int reaches and still be cut to the window.
    const std::int64_t left = bitmap.x, bottom = bitmap.y;
    const std::int64_t x0 = std::max<std::int64_t>(left, 0), x1 = std::min<std::int64_t>(left + bitmap.width, fb.width());
    const std::int64_t y0 = std::max<std::int64_t>(bottom, 0), y1 = std::min<std::int64_t>(bottom + bitmap.height, fb.height());
    const std::uint32_t rgba = fragmentRgba8(bitmap.color);
    const std::uint32_t z = toDepth24(bitmap.z);
    const auto color = fb.color();
    const auto depth = fb.depth();
    const std::size_t width = static_cast<std::size_t>(fb.width());
    for (std::int64_t y = y0; y < y1; ++y) {
        const std::uint8_t* row = bitmap.rows.data() + static_cast<std::size_t>(y - bottom) * bitmap.rowStride;
        for (std::int64_t x = x0; x < x1; ++x) {
            const std::int64_t bit = x - left;
            if (!(row[bit / 8] & (0x80 >> (bit % 8)))) continue;
            ++submitted_.fragments;
            const std::size_t index = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
            if (state.depthTest) {
                if (!depthPasses(state.depthFunc, z, depth[index])) continue;
                if (state.depthWrite) depth[index] = z;
            }
            ++submitted_.fragmentsPassed;
            ++submitted_.pixelsWritten;
            color[index] = rgba;
        }
    }
    fb.markWritten();
}

}  // namespace glrenderer
