#include "raster_triangle.h"

#include <immintrin.h>

#include <algorithm>
#include <cstddef>

#include "pixel_center_test.h"
#include "polygon_offset.h"

namespace glrenderer {
namespace {

// prepareTriangle loads a vertex's position and its secondary colour with the fog coordinate as
// four floats.
static_assert(offsetof(WindowVertex, fogCoord) == offsetof(WindowVertex, secondaryColor) + 3 * sizeof(float));
static_assert(offsetof(WindowVertex, z) == 2 * sizeof(float) && offsetof(WindowVertex, invW) == 3 * sizeof(float));

// Twice the area of a pixel, in fixed point (the unit of SetupTriangle::area).
constexpr std::int64_t kTwicePixelArea = std::int64_t{2} << (2 * kSubpixelBits);

// Floor and ceiling of a fixed-point value in whole pixels, for any sign.
std::int64_t floorToPixel(std::int64_t fixed) { return fixed >> kSubpixelBits; }
std::int64_t ceilToPixel(std::int64_t fixed) { return -((-fixed) >> kSubpixelBits); }

// The smallest and largest of three snapped coordinates, by value: std::min({...}) compiled to
// branches, and which vertex is leftmost is a coin toss per triangle (they mispredicted).
std::int64_t smallest(std::int64_t a, std::int64_t b, std::int64_t c) {
    const std::int64_t ab = b < a ? b : a;
    return c < ab ? c : ab;
}
std::int64_t largest(std::int64_t a, std::int64_t b, std::int64_t c) {
    const std::int64_t ab = b > a ? b : a;
    return c > ab ? c : ab;
}

}  // namespace

EdgeFunction::EdgeFunction(const FixedPoint& a, const FixedPoint& b) {
    const std::int64_t dx = a.y - b.y;  // dE per fixed-point unit of x
    const std::int64_t dy = b.x - a.x;
    // The edge owns its centers if dx > 0, or dx == 0 and dy < 0: if `leaning` is positive. The
    // bias is then 0, else -1, without a branch (the edge's direction is a coin toss per
    // triangle, and a branch on it mispredicted).
    const std::int64_t leaning = dx != 0 ? dx : -dy;
    stepX = dx << kSubpixelBits;
    stepY = dy << kSubpixelBits;
    valueAtOrigin = -(dy * a.y + dx * a.x) + ((leaning - 1) >> 63);
}

FragmentKey triangleFragmentKey(const DrawState& state, const Methods& methods) {
    FragmentKey key = fragmentKey(state);
    if (methods.hiddenSurface == HiddenSurface::PaintersSort) {
        key.depthTest = key.depthWrite = false;
        key.depthFunc = CompareFunc::Always;
        key.stencilDepthFail = StencilOp::Keep;
    }
    key.depthOffset = key.depthTest && state.polygonOffset.fill;
    key.polygonStipple = state.polygonStipple.active();
    if (key.shading == Shading::Perspective && methods.interpolation == Interpolation::ScreenLinear) {
        key.shading = Shading::Linear;
    }
    return key;
}

bool prepareTriangle(const SetupTriangle& t, const FragmentChoice& fragments, RasterMethod method,
                     const PixelRect& drawable, RasterTriangle& out) {
    // Orient the edges so that the interior is positive.
    const FixedPoint& a = t.fixed[0];
    const FixedPoint& b = t.area > 0 ? t.fixed[1] : t.fixed[2];
    const FixedPoint& c = t.area > 0 ? t.fixed[2] : t.fixed[1];
    std::int64_t minX = ceilToPixel(smallest(a.x, b.x, c.x)), maxX = floorToPixel(largest(a.x, b.x, c.x));
    std::int64_t minY = ceilToPixel(smallest(a.y, b.y, c.y)), maxY = floorToPixel(largest(a.y, b.y, c.y));
    out.method = method;
    out.depthSum = t.v[0]->z + t.v[1]->z + t.v[2]->z;
    if (method == RasterMethod::Scanline || method == RasterMethod::BoundingBoxFloat) {
        // Float methods may reach a pixel past the snapped bounds.
        --minX, ++maxX, --minY, ++maxY;
        for (int i = 0; i < 3; ++i) out.windowX[i] = t.v[i]->x, out.windowY[i] = t.v[i]->y;
    }
    out.minX = static_cast<int>(std::max<std::int64_t>(minX, drawable.minX));
    out.maxX = static_cast<int>(std::min<std::int64_t>(maxX, drawable.maxX));
    out.minY = static_cast<int>(std::max<std::int64_t>(minY, drawable.minY));
    out.maxY = static_cast<int>(std::min<std::int64_t>(maxY, drawable.maxY));
    if (out.minX > out.maxX || out.minY > out.maxY) return false;
    // The reference sets up planes only for triangles counter-clockwise in its y-down view; one
    // clockwise in GL's window (area > 0 here) is set up as (v1, v0, v2), keeping the provoking
    // vertex last. The planes' last bits follow that order.
    const bool clockwise = t.area > 0;
    const WindowVertex& v0 = clockwise ? *t.v[1] : *t.v[0];
    const WindowVertex& v1 = clockwise ? *t.v[0] : *t.v[1];
    const WindowVertex& v2 = *t.v[2];
    // (Before the edges: its division's wait then overlaps their set-up and the test below.)
    const PlaneBuilder planes(v0, v1, v2);
    out.edges[0] = EdgeFunction(a, b);
    out.edges[1] = EdgeFunction(b, c);
    out.edges[2] = EdgeFunction(c, a);
    // The exact methods cover the centers the edge functions hold, and nothing else. Tested only
    // below a pixel's area, where most such triangles are (in a dense mesh, 77% of those that
    // cover no center, and 39% of those tested): on every triangle the test cost more than
    // dropping saved.
    const bool exact = method == RasterMethod::Exact || method == RasterMethod::ExactPerPixel;
    const std::int64_t twiceArea = t.area > 0 ? t.area : -t.area;
    if (exact && twiceArea < kTwicePixelArea && PixelCenterTest::coversNone(out.edges, minX, maxX, minY, maxY)) {
        return false;
    }

    FragmentInputs& in = out.fragment;
    const FragmentKey& key = fragments.varyingW.key;
    const bool perspective = key.shading == Shading::Perspective;
    if (!perspective) in.setPath(fragments.varyingW);  // (perspective shading's comes with the plane of 1 / w)
    in.ops = fragments.ops;
    // (Past the first three cache lines, only what the key reads is written: RasterTriangle.)
    if (key.polygonStipple) in.polygonStipple = fragments.polygonStipple;
    // Flat shading is a constant in the reference, not an interpolation of equal colors.
    if (key.shading == Shading::Flat) {
        in.setFlatColor(*t.flatColor, t.v[2]->secondaryColor);  // every vertex has the flat secondary colour
        if (!key.depthTest && key.fog == FogMode::Off && key.textureEnv == TextureEnv::Off) return true;
    }
    // The planes in lanes of four, each vertex's values loaded as they lie in WindowVertex.
    const auto lanes = [&](auto valuesOf) { return planes.planes(valuesOf(v0), valuesOf(v1), valuesOf(v2)); };
    const auto oneOverW = [](const WindowVertex& v) { return _mm_set1_ps(v.invW); };
    if (key.shading != Shading::Flat) {
        lanes([&](const WindowVertex& v) {
            const __m128 color = _mm_loadu_ps(&v.color.x);
            return perspective ? _mm_mul_ps(color, oneOverW(v)) : color;
        }).store(in.color);
        if (key.colorSum) {  // (the fourth lane is the fog coordinate, left unused)
            lanes([&](const WindowVertex& v) {
                const __m128 secondary = _mm_loadu_ps(&v.secondaryColor.x);
                return perspective ? _mm_mul_ps(secondary, oneOverW(v)) : secondary;
            }).store(in.secondaryColor, 0, 3);
        }
    }
    // 1 / w, z and the fog coordinate / w: the planes invWAndDepth, and fogCoord (in the next
    // cache line: written only when read).
    if (perspective || key.depthTest || key.fog != FogMode::Off || key.textureEnv != TextureEnv::Off) {
        const FourPlanes depth = lanes([&](const WindowVertex& v) {
            const __m128 position = _mm_loadu_ps(&v.x);                                          // x, y, z, 1 / w
            const __m128 fogOverW = _mm_mul_ps(_mm_loadu_ps(&v.secondaryColor.x), oneOverW(v));  // in lane 3
            return _mm_shuffle_ps(position, fogOverW, _MM_SHUFFLE(3, 3, 2, 3));
        });
        depth.store(in.invWAndDepth);
        if (key.fog != FogMode::Off) depth.store(&in.fogCoord, 2, 1);
        // The path from the plane of 1 / w in registers: read back from the record just written, it
        // waited for the stores (a third of this function's time in the torus).
        if (perspective) {
            in.setPath(fragments.path(
                AttributePlane{_mm_cvtss_f32(depth.a0), _mm_cvtss_f32(depth.dadx), _mm_cvtss_f32(depth.dady)}));
        }
    }
    if (key.depthOffset) in.depthOffset = setupDepthOffset(fragments.polygonOffset, v0, v1, v2);
    if (key.fog != FogMode::Off) in.fog = fragments.fog;
    if (key.textureEnv != TextureEnv::Off) {
        in.setTextureImage(fragments.texture, fragments.textureEnvColor, fragments.textureBorderColor);
        // s, t and q divided by w: lanes s, t, r, q.
        const FourPlanes st =
            lanes([&](const WindowVertex& v) { return _mm_mul_ps(_mm_loadu_ps(&v.texCoord.x), oneOverW(v)); });
        st.store(in.texCoord, 0, 2);
        st.store(&in.texCoord[2], 3, 1);
    }
    return true;
}

void rasterizeTriangleExact(const RasterTriangle& t, const PixelRect& rect, Framebuffer& fb, FragmentCounts& counts) {
    const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
    const int minY = std::max(t.minY, rect.minY), maxY = std::min(t.maxY, rect.maxY);
    // One pixel at a time all through: the scalar routine of the triangle's key.
    const FragmentRoutine& scalar = scalarFragmentPaths().routine(t.fragment.key());
    for (int py = minY; py <= maxY; ++py) {
        std::int64_t e0 = t.edges[0].at(minX, py), e1 = t.edges[1].at(minX, py), e2 = t.edges[2].at(minX, py);
        int runBegin = -1;  // the first pixel of the covered run being walked
        for (int px = minX; px <= maxX + 1;
             ++px, e0 += t.edges[0].stepX, e1 += t.edges[1].stepX, e2 += t.edges[2].stepX) {
            const bool inside = px <= maxX && (e0 | e1 | e2) >= 0;
            if (inside && runBegin < 0) runBegin = px;
            if (!inside && runBegin >= 0) {
                scalar.span(t.fragment, py, runBegin, px - 1, fb, counts);
                runBegin = -1;
            }
        }
    }
}

}  // namespace glrenderer
