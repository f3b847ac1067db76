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

}  // namespace

void drawSmoothTriangle(const SmoothVertex& a, const SmoothVertex& b, const SmoothVertex& c,
                        const SmoothShading& shading, const glm::vec4& flatColor, CoverageShader coverage,
                        const FragmentChoice& fragments, const PixelRect& drawable, Framebuffer& framebuffer,
                        FragmentCounts& counts) {
    if (!isUsable(a.v) || !isUsable(b.v) || !isUsable(c.v)) return;
    const FixedPoint fa = snap(a.v), fb = snap(b.v), fc = snap(c.v);
    const std::int64_t area = fixedArea(fa, fb, fc);
    if (area == 0) return;
    // Edges oriented with the interior positive; planes anchored as setup anchors them (a
    // triangle clockwise in GL's window is set up as (b, a, c)).
    const bool clockwise = area > 0;
    const FixedPoint& e1 = clockwise ? fb : fc;
    const FixedPoint& e2 = clockwise ? fc : fb;
    const EdgeFunction edges[3] = {EdgeFunction(fa, e1), EdgeFunction(e1, e2), EdgeFunction(e2, fa)};
    const int minX = static_cast<int>(std::max<std::int64_t>(ceilToPixel(std::min({fa.x, fb.x, fc.x})), drawable.minX));
    const int maxX =
        static_cast<int>(std::min<std::int64_t>(floorToPixel(std::max({fa.x, fb.x, fc.x})), drawable.maxX));
    const int minY = static_cast<int>(std::max<std::int64_t>(ceilToPixel(std::min({fa.y, fb.y, fc.y})), drawable.minY));
    const int maxY =
        static_cast<int>(std::min<std::int64_t>(floorToPixel(std::max({fa.y, fb.y, fc.y})), drawable.maxY));
    if (minX > maxX || minY > maxY) return;

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
    const FragmentKey& key = fragments.varyingW.key;
    if (key.depthTest) fragment.depth = planes.plane(v0.z, v1.z, v2.z);
    if (key.fog != FogMode::Off) {
        fragment.fog = fragments.fog;
        fragment.invW = invW;
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

}  // namespace glrenderer
