// glBitmap's fragments: written straight into the framebuffer once everything queued before
// them is drawn, as the reference draws a bitmap after flushing its own vertex buffer.
#include <algorithm>

#include "batch_drawer.h"
#include "fragment_paths.h"
#include "pixel_rect.h"
#include "triangle_setup.h"
#include "glrenderer/pipeline.h"

namespace glrenderer {
namespace {

// The texture planes of a bitmap's fragments (BitmapTexCoords), in internal rows of a
// framebuffer `height` high: constant, or those of the reference's quad over the bitmap's
// rectangle, through three of its corners as setup builds a triangle's.
void setBitmapTexture(FragmentInputs& fragment, const FragmentChoice& fragments, const Bitmap& bitmap, int height) {
    const auto texture = [&](const auto& planes, const auto&... corners) {
        fragment.setTexture(fragments.texture, fragments.textureEnvColor, fragments.textureBorderColor, planes,
                            corners...);
    };
    if (!bitmap.texCoords.vary) {
        WindowVertex constant;
        constant.texCoord = bitmap.texCoords.current;
        return texture(ConstantPlanes{}, constant);
    }
    const float left = static_cast<float>(bitmap.x), right = static_cast<float>(std::int64_t{bitmap.x} + bitmap.width);
    const float bottom = static_cast<float>(height - std::int64_t{bitmap.y});
    const float top = static_cast<float>(height - (std::int64_t{bitmap.y} + bitmap.height));
    WindowVertex lowerLeft, lowerRight, upperRight;
    lowerLeft.x = left, lowerLeft.y = bottom, lowerLeft.texCoord = {0.0f, 0.0f, 0.0f, 1.0f};
    lowerRight.x = right, lowerRight.y = bottom, lowerRight.texCoord = {1.0f, 0.0f, 0.0f, 1.0f};
    upperRight.x = right, upperRight.y = top, upperRight.texCoord = {1.0f, 1.0f, 0.0f, 1.0f};
    texture(PlaneBuilder(lowerLeft, lowerRight, upperRight), lowerLeft, lowerRight, upperRight);
}

}  // namespace

void Pipeline::drawBitmap(const DrawState& state, const Bitmap& bitmap) {
    finish();
    Framebuffer& fb = drawer_->framebuffer();
    // In 64 bits: a bitmap may start anywhere an int reaches and still be cut to the window.
    const std::int64_t left = bitmap.x, bottom = bitmap.y;
    // Cut to the drawable rect, in GL's rows (y up): [x0, x1) x [y0, y1).
    const PixelRect drawable = drawableRect(state.fragmentOps.scissor, fb.width(), fb.height());
    const std::int64_t x0 = std::max<std::int64_t>(left, drawable.minX);
    const std::int64_t x1 = std::min<std::int64_t>(left + bitmap.width, std::int64_t{drawable.maxX} + 1);
    const std::int64_t y0 = std::max<std::int64_t>(bottom, fb.height() - 1 - drawable.maxY);
    const std::int64_t y1 = std::min<std::int64_t>(bottom + bitmap.height, fb.height() - drawable.minY);
    // Runs of set bits, in each row, are spans of one colour and depth for the fragment stage.
    FragmentInputs fragment;
    const FragmentChoice fragments(bestFragmentPaths(), flatFragmentKey(state), state);
    fragment.setPath(fragments.varyingW);
    fragment.ops = fragments.ops;
    fragment.setFlatColor(bitmap.color);
    fragment.setDepth({bitmap.z, 0.0f, 0.0f});  // z at every pixel: 0 * x + z is z
    // Fog: the reference's bitmap quad carries no fog coordinate, so its fragments read 0 (not
    // the raster distance): LINEAR fog gives the factor of distance 0, EXP and EXP2 none.
    fragment.fog = state.fog;
    fragment.setInvW({1.0f, 0.0f, 0.0f});
    fragment.fogCoord = {0.0f, 0.0f, 0.0f};
    if (fragment.key().textureEnv != TextureEnv::Off) setBitmapTexture(fragment, fragments, bitmap, fb.height());
    FragmentCounts counts;
    for (std::int64_t y = y0; y < y1; ++y) {
        const std::uint8_t* row = bitmap.rows.data() + static_cast<std::size_t>(y - bottom) * bitmap.rowStride;
        const auto isSet = [&](std::int64_t x) { return (row[(x - left) / 8] & (0x80 >> ((x - left) % 8))) != 0; };
        const int internalRow = fb.height() - 1 - static_cast<int>(y);
        for (std::int64_t x = x0; x < x1; ++x) {
            if (!isSet(x)) continue;
            const std::int64_t runBegin = x;
            while (x + 1 < x1 && isSet(x + 1)) ++x;
            fragment.shadeSpan(internalRow, static_cast<int>(runBegin), static_cast<int>(x), fb, counts);
        }
    }
    addFragmentCounts(submitted_, counts);
    fb.markWritten();
}

}  // namespace glrenderer
