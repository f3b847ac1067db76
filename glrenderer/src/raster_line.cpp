#include "raster_line.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "pixel_rect.h"
#include "round_half_away.h"
#include "triangle_setup.h"

namespace glrenderer {
namespace {

// Ends beyond this many pixels cannot come out of clipping against a real viewport; refusing
// them keeps every fixed-point product below 2^62.
constexpr float kMaxLineCoordinate = 1 << 22;
// The reference's maximum line width.
constexpr float kMaxLineWidth = 255.0f;

// The reference's sign test counts zero as positive.
bool nonNegative(float v) { return v >= 0.0f; }
float fraction(float v) { return v - std::floor(v); }

// The four corners of the parallelogram the reference rasterizes, in fixed point relative to
// pixel centers, wound so that the interior is on the positive side of each edge function.
struct LineQuad {
    std::int64_t x[4], y[4];
};

// How far, in pixels, each end of the segment is moved along the major axis.
struct EndOffsets {
    float startMajor = 0, startMinor = 0, endMajor = 0, endMinor = 0;
};

// Diamond-exit rule: a line lights the pixel holding an end only if it leaves that pixel's
// diamond (|dx| + |dy| < 1/2 around the center). The tests below are the reference's, per
// major axis; `*diff` are the ends' offsets from their pixel centers, (dx, dy) = start - end.
bool xMajorDrawsStart(float x1diff, float y1diff, float y1, float dx, float dy, float dydx) {
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) return true;
    if (nonNegative(x1diff) == nonNegative(-dx)) return false;
    if (nonNegative(-y1diff) != nonNegative(dy)) return true;
    const float intersect = fraction(y1) + x1diff * dydx;
    return intersect < 1.0f && intersect > 0.0f;
}

bool xMajorDrawsEnd(float x2diff, float y2diff, float y2, float dx, float dy, float dydx) {
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) return false;
    if (nonNegative(x2diff) != nonNegative(-dx)) return false;
    if (nonNegative(-y2diff) == nonNegative(dy)) return true;
    const float intersect = fraction(y2) + x2diff * dydx;
    return intersect < 1.0f && intersect > 0.0f;
}

bool yMajorDrawsStart(float x1diff, float y1diff, float x1, float dx, float dy, float dxdy) {
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) return true;
    if (nonNegative(-y1diff) == nonNegative(dy)) return false;
    if (nonNegative(x1diff) != nonNegative(-dx)) return true;
    const float intersect = fraction(x1) + y1diff * dxdy;
    return intersect < 1.0f && intersect > 0.0f;
}

// Unlike the x-major end test, the low bound of the intersection is inclusive here.
bool yMajorDrawsEnd(float x2diff, float y2diff, float x2, float dx, float dy, float dxdy) {
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) return false;
    if (nonNegative(-y2diff) != nonNegative(dy)) return false;
    if (nonNegative(x2diff) == nonNegative(-dx)) return true;
    const float intersect = fraction(x2) + y2diff * dxdy;
    return intersect < 1.0f && intersect >= 0.0f;
}

// Builds the quad for start (x1, y1) -> end (x2, y2) with an integer width in fixed point.
LineQuad buildQuad(float x1, float y1, float x2, float y2, std::int64_t fixedWidth) {
    const float dx = x1 - x2;
    const float dy = y1 - y2;
    const float x1diff = x1 - std::floor(x1) - 0.5f;
    const float y1diff = y1 - std::floor(y1) - 0.5f;
    float x2diff = x2 - std::floor(x2) - 0.5f;
    float y2diff = y2 - std::floor(y2) - 0.5f;
    const std::int64_t half = fixedWidth / 2;
    LineQuad q;
    if (std::fabs(dx) >= std::fabs(dy)) {
        const float dydx = dy / dx;
        if (y2diff == -0.5f && dy < 0.0f) y2diff = 0.5f;
        const bool drawStart = xMajorDrawsStart(x1diff, y1diff, y1, dx, dy, dydx);
        const bool drawEnd = xMajorDrawsEnd(x2diff, y2diff, y2, dx, dy, dydx);
        // The quad spans from the left end to the right end; which pixel an end lights
        // without offsets depends on which side of its pixel center it lies.
        float xOffset = 0, yOffset = 0, xOffsetEnd = 0, yOffsetEnd = 0;
        float leftX = x1, leftY = y1, rightX = x2, rightY = y2;
        if (dx < 0.0f) {
            // Start is the left end: the quad's "first" corner pair belongs to the right end.
            std::swap(leftX, rightX);
            std::swap(leftY, rightY);
            if ((x1diff <= 0.0f) != drawStart) {
                xOffsetEnd = -x1diff - 0.5f;
                yOffsetEnd = xOffsetEnd * dydx;
            }
            if ((x2diff >= 0.0f) != drawEnd) {  // an end on a pixel center counts as drawn
                xOffset = -x2diff - 0.5f;
                yOffset = xOffset * dydx;
            }
        } else {
            if ((x1diff > 0.0f) != drawStart) {
                xOffset = -x1diff + 0.5f;
                yOffset = xOffset * dydx;
            }
            if ((x2diff <= 0.0f) != drawEnd) {
                xOffsetEnd = -x2diff + 0.5f;
                yOffsetEnd = xOffsetEnd * dydx;
            }
        }
        // After the swap (leftX, leftY) is the reference's "v1": the right end when dx < 0.
        const std::int64_t ax = toFixedHalfAway(leftX + xOffset - 0.5f);
        const std::int64_t bx = toFixedHalfAway(rightX + xOffsetEnd - 0.5f);
        const std::int64_t ay = toFixedHalfAway(leftY + yOffset - 0.5f);
        const std::int64_t by = toFixedHalfAway(rightY + yOffsetEnd - 0.5f);
        q = {{ax, bx, bx, ax}, {ay - half, by - half, by + half, ay + half}};
    } else {
        const float dxdy = dx / dy;
        if (x2diff == -0.5f && dx < 0.0f) x2diff = 0.5f;
        const bool drawStart = yMajorDrawsStart(x1diff, y1diff, x1, dx, dy, dxdy);
        const bool drawEnd = yMajorDrawsEnd(x2diff, y2diff, x2, dx, dy, dxdy);
        float xOffset = 0, yOffset = 0, xOffsetEnd = 0, yOffsetEnd = 0;
        float topX = x1, topY = y1, bottomX = x2, bottomY = y2;
        if (dy > 0.0f) {
            std::swap(topX, bottomX);
            std::swap(topY, bottomY);
            if ((y1diff >= 0.0f) != drawStart) {
                yOffsetEnd = -y1diff + 0.5f;
                xOffsetEnd = yOffsetEnd * dxdy;
            }
            if ((y2diff <= 0.0f) != drawEnd) {  // an end on a pixel center counts as drawn
                yOffset = -y2diff + 0.5f;
                xOffset = yOffset * dxdy;
            }
        } else {
            if ((y1diff < 0.0f) != drawStart) {
                yOffset = -y1diff - 0.5f;
                xOffset = yOffset * dxdy;
            }
            if ((y2diff >= 0.0f) != drawEnd) {
                yOffsetEnd = -y2diff - 0.5f;
                xOffsetEnd = yOffsetEnd * dxdy;
            }
        }
        const std::int64_t ax = toFixedHalfAway(topX + xOffset - 0.5f);
        const std::int64_t bx = toFixedHalfAway(bottomX + xOffsetEnd - 0.5f);
        const std::int64_t ay = toFixedHalfAway(topY + yOffset - 0.5f);
        const std::int64_t by = toFixedHalfAway(bottomY + yOffsetEnd - 0.5f);
        q = {{ax - half, bx - half, bx + half, ax + half}, {ay, by, by, ay}};
    }
    return q;
}

// One edge of the quad as the reference evaluates it: value(p) = c - dcdx*px + dcdy*py in
// fixed point, inside when > 0. Left edges and, under the bottom-edge rule, edges with the
// interior above them in GL own the pixel centers on them (c is one larger).
struct LineEdge {
    std::int64_t dcdx, dcdy, c;
    LineEdge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by)
        : dcdx(ay - by), dcdy(ax - bx), c(dcdx * ax - dcdy * ay) {
        if (dcdx < 0 || (dcdx == 0 && dcdy < 0)) ++c;
    }
};

std::int64_t floorDiv(std::int64_t n, std::int64_t d) {  // d > 0
    const std::int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

// The attribute planes of a line, built from the unsnapped ends as the reference builds them:
// the gradient lies along the major axis only ("wide line" interpolation), anchored at `start`.
class LinePlaneBuilder {
public:
    LinePlaneBuilder(const WindowVertex& start, const WindowVertex& end)
        : x1Center_(start.x - 0.5f), y1Center_(start.y - 0.5f) {
        const float dx = start.x - end.x;
        const float dy = start.y - end.y;
        oneOverLengthSquared_ = 1.0f / (dx * dx + dy * dy);
        if (std::fabs(dx) >= std::fabs(dy)) {
            const float dydx = dy / dx;
            dx_ = dx * (1.0f + dydx * dydx);
            dy_ = 0.0f;
        } else {
            const float dxdy = dx / dy;
            dx_ = 0.0f;
            dy_ = dy * (1.0f + dxdy * dxdy);
        }
    }
    AttributePlane plane(float a1, float a2) const {
        const float da21 = a1 - a2;
        AttributePlane p;
        p.dadx = da21 * dx_ * oneOverLengthSquared_;
        p.dady = da21 * dy_ * oneOverLengthSquared_;
        p.a0 = a1 - (p.dadx * x1Center_ + p.dady * y1Center_);
        return p;
    }

private:
    float dx_, dy_, oneOverLengthSquared_, x1Center_, y1Center_;
};

// The pixels the quad may cover: the reference's bounding box (rounded for the bottom-left
// convention) cut to the drawable rect; empty (minX > maxX or minY > maxY) when they do not meet.
PixelRect quadBounds(const LineQuad& q, const PixelRect& drawable) {
    if (drawable.minX > drawable.maxX || drawable.minY > drawable.maxY) return drawable;
    const std::int64_t one = 1 << kSubpixelBits;
    const auto [minX, maxX] = std::minmax({q.x[0], q.x[1], q.x[2], q.x[3]});
    const auto [minY, maxY] = std::minmax({q.y[0], q.y[1], q.y[2], q.y[3]});
    // Lows at least the drawable's, highs at most its (in 64 bits, then within one of it).
    const auto low = [](std::int64_t v, int min, int max) {
        return static_cast<int>(std::clamp<std::int64_t>(v, min, std::int64_t{max} + 1));
    };
    const auto high = [](std::int64_t v, int min, int max) {
        return static_cast<int>(std::clamp<std::int64_t>(v, std::int64_t{min} - 1, max));
    };
    return {low((minX + one - 1) >> kSubpixelBits, drawable.minX, drawable.maxX),
            high(((maxX + one - 1) >> kSubpixelBits) - 1, drawable.minX, drawable.maxX),
            low((minY + one) >> kSubpixelBits, drawable.minY, drawable.maxY),
            high(((maxY + one) >> kSubpixelBits) - 1, drawable.minY, drawable.maxY)};
}

// A line's quad queued for the tiles: per row, the span its four edges bound, through the
// fragment stage.
class QueuedLine final : public TiledPrimitive {
public:
    QueuedLine(const LineQuad& q, const PixelRect& pixels, const FragmentInputs& fragment, float depth)
        : TiledPrimitive(pixels, depth),
          edges_{LineEdge(q.x[0], q.y[0], q.x[1], q.y[1]), LineEdge(q.x[1], q.y[1], q.x[2], q.y[2]),
                 LineEdge(q.x[2], q.y[2], q.x[3], q.y[3]), LineEdge(q.x[3], q.y[3], q.x[0], q.y[0])},
          fragment_(fragment) {}

    void draw(const PixelRect& tile, Framebuffer& fb, FragmentCounts& counts) const override {
        const std::int64_t one = 1 << kSubpixelBits;
        const int minX = std::max(bounds.minX, tile.minX), maxX = std::min(bounds.maxX, tile.maxX);
        const int minY = std::max(bounds.minY, tile.minY), maxY = std::min(bounds.maxY, tile.maxY);
        for (std::int64_t py = minY; py <= maxY; ++py) {
            // Each edge bounds the row's span: value(px) = a * px + b > 0.
            std::int64_t first = minX, last = maxX;
            for (const LineEdge& e : edges_) {
                const std::int64_t a = -e.dcdx * one;
                const std::int64_t b = e.c + e.dcdy * py * one;
                if (a > 0)
                    first = std::max(first, floorDiv(-b, a) + 1);
                else if (a < 0)
                    last = std::min(last, -floorDiv(-b, -a) - 1);
                else if (b <= 0)
                    last = first - 1;
            }
            if (first <= last) {
                fragment_.shadeSpan(static_cast<int>(py), static_cast<int>(first), static_cast<int>(last), fb, counts);
            }
        }
    }

private:
    LineEdge edges_[4];
    FragmentInputs fragment_;
};

bool isUsable(const WindowVertex& v) {
    return std::fabs(v.x) < kMaxLineCoordinate && std::fabs(v.y) < kMaxLineCoordinate && std::isfinite(v.z) &&
           std::isfinite(v.invW);
}

}  // namespace

void queueLine(const WindowVertex& start, const WindowVertex& end, const glm::vec4& flatColor, float lineWidth,
               const FragmentChoice& fragments, const PixelRect& drawable, PrimitiveQueue& queue) {
    if (!isUsable(start) || !isUsable(end)) return;
    if (start.x == end.x && start.y == end.y) return;  // zero length draws nothing
    // Width rounded to an integer (halves up), at least one pixel; NaN draws as 1, as the
    // reference's comparisons with NaN all fail.
    const float width = lineWidth > 1.0f ? std::min(lineWidth, kMaxLineWidth) : 1.0f;
    const std::int64_t fixedWidth = roundHalfAway(width) << kSubpixelBits;
    const LineQuad quad = buildQuad(start.x, start.y, end.x, end.y, fixedWidth);
    const PixelRect bounds = quadBounds(quad, drawable);
    if (bounds.minX > bounds.maxX || bounds.minY > bounds.maxY) return;

    const LinePlaneBuilder builder(start, end);
    FragmentInputs fragment;
    fragment.setPath(fragments.varyingW);
    fragment.ops = fragments.ops;
    fragment.polygonStipple = fragments.polygonStipple;  // with a key that has it (unfilled faces')
    const FragmentKey& key = fragments.varyingW.key;
    if (key.shading == Shading::Flat) {
        fragment.setFlatColor(flatColor, start.secondaryColor);  // both ends carry the flat secondary colour
    } else {
        for (int c = 0; c < 4; ++c) {
            fragment.color.set(c, builder.plane(start.color[c] * start.invW, end.color[c] * end.invW));
        }
        if (key.colorSum) {
            for (int c = 0; c < 3; ++c) {
                fragment.secondaryColor[c] =
                    builder.plane(start.secondaryColor[c] * start.invW, end.secondaryColor[c] * end.invW);
            }
        }
        fragment.setInvW(builder.plane(start.invW, end.invW));
        fragment.setPath(fragments.path(fragment.invW()));
    }
    if (key.depthTest) fragment.setDepth(builder.plane(start.z, end.z));
    if (key.fog != FogMode::Off) {
        fragment.fog = fragments.fog;
        fragment.setInvW(builder.plane(start.invW, end.invW));
        fragment.fogCoord = builder.plane(start.fogCoord * start.invW, end.fogCoord * end.invW);
    }
    if (key.textureEnv != TextureEnv::Off) {
        fragment.setTexture(fragments.texture, fragments.textureEnvColor, fragments.textureBorderColor, builder, start,
                            end);
    }
    queue.queue(queue.make<QueuedLine>(quad, bounds, fragment, 0.5f * (start.z + end.z)));
}

}  // namespace glrenderer
