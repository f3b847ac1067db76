#include "smooth_triangle.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster_triangle.h"
#include "triangle_setup.h"

namespace glrenderer {
namespace {

std::int64_t floorToPixel(std::int64_t fixed) { return fixed >> kSubpixelBits; }
std::int64_t ceilToPixel(std::int64_t fixed) { return -((-fixed) >> kSubpixelBits); }

// Positions beyond this cannot come from a real viewport; refusing them keeps the fixed-point
// products in range.
constexpr float kMaxCoordinate = 1 << 22;

bool isUsable(const WindowVertex& v) {
    return std::fabs(v.x) < kMaxCoordinate && std::fabs(v.y) < kMaxCoordinate && std::isfinite(v.z) &&
           std::isfinite(v.invW);
}

// The pixels in `area` the triangle may cover; empty (minX > maxX or minY > maxY) when it draws
// nothing there.
PixelRect smoothTriangleBounds(const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                               const PixelRect& area) {
    constexpr PixelRect kNothing{0, -1, 0, -1};
    if (!isUsable(a.v) || !isUsable(b.v) || !isUsable(c.v)) return kNothing;
    const FixedPoint fa = snap(a.v), fb = snap(b.v), fc = snap(c.v);
    if (fixedArea(fa, fb, fc) == 0) return kNothing;
    const auto low = [](std::int64_t fixed, int min) {
        return static_cast<int>(std::max<std::int64_t>(ceilToPixel(fixed), min));
    };
    const auto high = [](std::int64_t fixed, int max) {
        return static_cast<int>(std::min<std::int64_t>(floorToPixel(fixed), max));
    };
    return {low(std::min({fa.x, fb.x, fc.x}), area.minX), high(std::max({fa.x, fb.x, fc.x}), area.maxX),
            low(std::min({fa.y, fb.y, fc.y}), area.minY), high(std::max({fa.y, fb.y, fc.y}), area.maxY)};
}

// Draws the triangle's fragments in `area` (see queueSmoothTriangle).
void drawSmoothTriangle(const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                        const SmoothShading& shading, const glm::vec4& flatColor, CoverageShader coverage,
                        const FragmentChoice& fragments, const PixelRect& area, Framebuffer& framebuffer,
                        FragmentCounts& counts) {
    const PixelRect bounds = smoothTriangleBounds(a, b, c, area);
    if (bounds.minX > bounds.maxX || bounds.minY > bounds.maxY) return;
    const FixedPoint fa = snap(a.v), fb = snap(b.v), fc = snap(c.v);
    const std::int64_t area2 = fixedArea(fa, fb, fc);
    // Edges oriented with the interior positive; planes anchored as setup anchors them (a
    // triangle clockwise in GL's window is set up as (b, a, c)).
    const bool clockwise = area2 > 0;
    const FixedPoint& e1 = clockwise ? fb : fc;
    const FixedPoint& e2 = clockwise ? fc : fb;
    const EdgeFunction edges[3] = {EdgeFunction(fa, e1), EdgeFunction(e1, e2), EdgeFunction(e2, fa)};
    const auto [minX, maxX, minY, maxY] = bounds;

    const SmoothVertex& s0 = clockwise ? b : a;
    const SmoothVertex& s1 = clockwise ? a : b;
    const SmoothVertex& s2 = c;
    const WindowVertex &v0 = s0.v, &v1 = s1.v, &v2 = s2.v;
    const PlaneBuilder planes(v0, v1, v2);
    const auto perspective = [&](float q0, float q1, float q2) {
        return planes.plane(q0 * v0.invW, q1 * v1.invW, q2 * v2.invW);
    };
    AttributePlane color[4], secondary[3], aa[4];
    for (int i = 0; i < 4; ++i) {
        color[i] = perspective(v0.color[i], v1.color[i], v2.color[i]);
        aa[i] = perspective(s0.aa[i], s1.aa[i], s2.aa[i]);
    }
    for (int i = 0; i < 3; ++i) {
        secondary[i] = perspective(v0.secondaryColor[i], v1.secondaryColor[i], v2.secondaryColor[i]);
    }
    const AttributePlane invW = planes.plane(v0.invW, v1.invW, v2.invW);

    FragmentInputs fragment;
    fragment.setPath(fragments.varyingW);
    fragment.ops = fragments.ops;
    fragment.polygonStipple = fragments.polygonStipple;  // with a key that has it (unfilled faces')
    const FragmentKey& key = fragments.varyingW.key;
    if (key.depthTest) fragment.setDepth(planes.plane(v0.z, v1.z, v2.z));
    if (key.fog != FogMode::Off) {
        fragment.fog = fragments.fog;
        fragment.setInvW(invW);
        fragment.fogCoord = perspective(v0.fogCoord, v1.fogCoord, v2.fogCoord);
    }
    if (key.textureEnv != TextureEnv::Off) {
        fragment.setTexture(fragments.texture, fragments.textureEnvColor, fragments.textureBorderColor, planes, v0, v1,
                            v2);
    }
    for (int py = minY; py <= maxY; ++py) {
        for (int px = minX; px <= maxX; ++px) {
            if ((edges[0].at(px, py) | edges[1].at(px, py) | edges[2].at(px, py)) < 0) continue;
            const float w = 1.0f / invW.at(static_cast<float>(px), static_cast<float>(py));
            const auto value = [&](const AttributePlane& p) {
                return p.at(static_cast<float>(px), static_cast<float>(py)) * w;
            };
            const Coverage cover = coverage({value(aa[0]), value(aa[1]), value(aa[2]), value(aa[3])});
            if (!cover.kept) continue;
            glm::vec4 rgba = flatColor;
            glm::vec3 specular = v2.secondaryColor;
            if (!shading.flat) {
                rgba = {value(color[0]), value(color[1]), value(color[2]), value(color[3])};
                specular = {value(secondary[0]), value(secondary[1]), value(secondary[2])};
            }
            fragment.setFlatColor(shading.covered(rgba, cover.factor), specular);
            fragment.shadeSpan(py, px, px, framebuffer, counts);
        }
    }
}

// A smooth primitive's triangle queued for the tiles, with everything it is drawn with.
class QueuedSmoothTriangle final : public TiledPrimitive {
public:
    QueuedSmoothTriangle(const PixelRect& pixels, const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                         const SmoothShading& shading, const glm::vec4& flatColor, CoverageShader coverage,
                         const FragmentChoice& fragments)
        : TiledPrimitive(pixels, (a.v.z + b.v.z + c.v.z) / 3.0f),
          v_{a, b, c},
          shading_(shading),
          flatColor_(flatColor),
          coverage_(coverage),
          fragments_(fragments) {}

    void draw(const PixelRect& tile, Framebuffer& fb, FragmentCounts& counts) const override {
        const PixelRect area{std::max(bounds.minX, tile.minX), std::min(bounds.maxX, tile.maxX),
                             std::max(bounds.minY, tile.minY), std::min(bounds.maxY, tile.maxY)};
        drawSmoothTriangle(v_[0], v_[1], v_[2], shading_, flatColor_, coverage_, fragments_, area, fb, counts);
    }

private:
    SmoothVertex v_[3];
    SmoothShading shading_;
    glm::vec4 flatColor_;
    CoverageShader coverage_;
    FragmentChoice fragments_;
};

}  // namespace

void queueSmoothTriangle(const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                         const SmoothShading& shading, const glm::vec4& flatColor, CoverageShader coverage,
                         const FragmentChoice& fragments, const PixelRect& drawable, PrimitiveQueue& queue) {
    const PixelRect bounds = smoothTriangleBounds(a, b, c, drawable);
    if (bounds.minX > bounds.maxX || bounds.minY > bounds.maxY) return;
    queue.queue(queue.make<QueuedSmoothTriangle>(bounds, a, b, c, shading, flatColor, coverage, fragments));
}

}  // namespace glrenderer
