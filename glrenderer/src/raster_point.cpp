#include "raster_point.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "pixel_rect.h"
#include "round_half_away.h"
#include "triangle_setup.h"

namespace glrenderer {
namespace {

constexpr float kMaxPointCoordinate = 1 << 22;
// The reference's maximum point size.
constexpr float kMaxPointSize = 255.0f;

// Planes of one value at every pixel.
struct PixelBox {
    std::int64_t x0, y0, x1, y1;  // inclusive
};

// The covered pixels in internal (y-down) rows. The snapped y is lowered by one 1/256 step
// first (the reference's bottom-edge adjustment): centers exactly on a pixel boundary go down
// in GL coordinates. Size 1 takes the pixel holding the center, odd sizes grow around it, even
// sizes around the nearest pixel corner. Sizes round to an integer with halves going down.
PixelBox pointBox(const WindowVertex& v, float size) {
    const std::int64_t x = toFixedHalfAway(v.x);
    const std::int64_t y = toFixedHalfAway(v.y) - 1;
    const std::int64_t rounded = (toFixedHalfAway(size) + (1 << kSubpixelBits) / 2 - 1) >> kSubpixelBits;
    const std::int64_t s = std::max<std::int64_t>(rounded, 1);
    std::int64_t x0, y0;
    if (s % 2 == 1) {
        x0 = (x >> kSubpixelBits) - (s - 1) / 2;
        y0 = (y >> kSubpixelBits) - (s - 1) / 2;
    } else {
        x0 = ((x + 128) >> kSubpixelBits) - s / 2;
        y0 = ((y + 128) >> kSubpixelBits) - s / 2;
    }
    return {x0, y0, x0 + s - 1, y0 + s - 1};
}

// A point's square queued for the tiles: one constant colour and depth.
class QueuedPoint final : public TiledPrimitive {
public:
    QueuedPoint(const PixelRect& pixels, const FragmentInputs& fragment, float depth)
        : TiledPrimitive(pixels, depth), fragment_(fragment) {}

    void draw(const PixelRect& tile, Framebuffer& fb, FragmentCounts& counts) const override {
        const int minX = std::max(bounds.minX, tile.minX), maxX = std::min(bounds.maxX, tile.maxX);
        const int minY = std::max(bounds.minY, tile.minY), maxY = std::min(bounds.maxY, tile.maxY);
        if (minX > maxX) return;
        for (int row = minY; row <= maxY; ++row) fragment_.shadeSpan(row, minX, maxX, fb, counts);
    }

private:
    FragmentInputs fragment_;
};

}  // namespace

void queuePoint(const WindowVertex& point, const DrawState& state, const FragmentChoice& fragments,
                const PixelRect& drawable, PrimitiveQueue& queue) {
    if (!(std::fabs(point.x) < kMaxPointCoordinate && std::fabs(point.y) < kMaxPointCoordinate &&
          std::isfinite(point.z) && std::isfinite(point.invW))) {
        return;
    }
    const float size = state.pointSize > 1.0f ? std::min(state.pointSize, kMaxPointSize) : 1.0f;  // NaN: 1
    PixelBox box = pointBox(point, size);
    box.x0 = std::max<std::int64_t>(box.x0, drawable.minX);
    box.y0 = std::max<std::int64_t>(box.y0, drawable.minY);
    box.x1 = std::min<std::int64_t>(box.x1, drawable.maxX);
    box.y1 = std::min<std::int64_t>(box.y1, drawable.maxY);
    if (box.x0 > box.x1 || box.y0 > box.y1) return;

    // The color is set up divided by w and multiplied back per fragment, as for any
    // perspective-correct attribute of the reference; flat colors are used as they are.
    glm::vec4 c = point.color;
    glm::vec3 secondary = point.secondaryColor;
    if (state.shadeModel == ShadeModel::Smooth) {
        c = c * point.invW * (1.0f / point.invW);
        secondary = secondary * point.invW * (1.0f / point.invW);
    }
    FragmentInputs fragment;
    fragment.setPath(fragments.varyingW);
    fragment.ops = fragments.ops;
    fragment.polygonStipple = fragments.polygonStipple;  // with a key that has it (unfilled faces')
    fragment.setFlatColor(c, secondary);
    fragment.setDepth({point.z, 0.0f, 0.0f});  // z at every pixel: 0 * x + z is z
    if (fragment.key().fog != FogMode::Off) {  // the fog coordinate as a perspective attribute, as the colour
        fragment.fog = fragments.fog;
        fragment.setInvW({point.invW, 0.0f, 0.0f});
        fragment.fogCoord = {point.fogCoord * point.invW, 0.0f, 0.0f};
    }
    if (fragment.key().textureEnv != TextureEnv::Off) {
        fragment.setTexture(fragments.texture, fragments.textureEnvColor, fragments.textureBorderColor,
                            ConstantPlanes{}, point);
    }
    const PixelRect bounds{static_cast<int>(box.x0), static_cast<int>(box.x1), static_cast<int>(box.y0),
                           static_cast<int>(box.y1)};
    queue.queue(queue.make<QueuedPoint>(bounds, fragment, point.z));
}

}  // namespace glrenderer
