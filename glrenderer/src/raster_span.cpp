#include "raster_span.h"

#include <algorithm>
#include <cstdlib>

#include "glrenderer/invariant.h"

namespace glrenderer {
namespace {

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {  // b > 0
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
std::int64_t ceilDiv(std::int64_t a, std::int64_t b) { return -floorDiv(-a, b); }  // b > 0

// Up to this many columns, testing pixels costs less than the three 64-bit divisions.
constexpr int kScannedColumns = 4;

// Each pixel's test from the left for the first covered one, then from the right for the last
// (a row's covered pixels are contiguous).
Span scannedSpan(const RasterTriangle& t, int row, int minX, int maxX) {
    if (minX > maxX) return {1, 0};
    std::int64_t e0 = t.edges[0].at(minX, row), e1 = t.edges[1].at(minX, row), e2 = t.edges[2].at(minX, row);
    int begin = minX;
    while ((e0 | e1 | e2) < 0) {
        if (begin == maxX) return {1, 0};
        ++begin, e0 += t.edges[0].stepX, e1 += t.edges[1].stepX, e2 += t.edges[2].stepX;
    }
    const int columns = maxX - begin;
    e0 += t.edges[0].stepX * columns, e1 += t.edges[1].stepX * columns, e2 += t.edges[2].stepX * columns;
    int end = maxX;  // stops at `begin` at the latest, which is covered
    while ((e0 | e1 | e2) < 0) --end, e0 -= t.edges[0].stepX, e1 -= t.edges[1].stepX, e2 -= t.edges[2].stepX;
    return {begin, end};
}

Span dividedSpan(const RasterTriangle& t, int row, int minX, int maxX) {
    std::int64_t begin = minX, end = maxX;
    for (const EdgeFunction& edge : t.edges) {
        // Inside where value + stepX * x >= 0.
        const std::int64_t value = edge.valueAtOrigin + edge.stepY * row;
        if (edge.stepX > 0)
            begin = std::max(begin, ceilDiv(-value, edge.stepX));
        else if (edge.stepX < 0)
            end = std::min(end, floorDiv(value, -edge.stepX));
        else if (value < 0)
            return {1, 0};
    }
    if (begin > end) return {1, 0};
    return {static_cast<int>(begin), static_cast<int>(end)};
}

}  // namespace

SteppedRows::SteppedRows(const RasterTriangle& t, int minX, int maxX, int row) : minX_(minX), maxX_(maxX) {
    for (int k = 0; k < 3; ++k) {
        const EdgeFunction& edge = t.edges[k];
        const std::int64_t value = edge.valueAtOrigin + edge.stepY * row;
        const std::int64_t divisor = edge.stepX == 0 ? 1 : std::abs(edge.stepX);
        const Bound::Kind kind = edge.stepX > 0 ? Bound::Begin : edge.stepX < 0 ? Bound::End : Bound::Row;
        const std::int64_t quotient = floorDiv(value, divisor), stepQuotient = floorDiv(edge.stepY, divisor);
        bounds_[k] = {kind,   quotient, value - quotient * divisor, stepQuotient, edge.stepY - stepQuotient * divisor,
                      divisor};
    }
}

Span coveredSpan(const RasterTriangle& t, int row, int minX, int maxX) {
    const Span span = maxX - minX < kScannedColumns ? scannedSpan(t, row, minX, maxX) : dividedSpan(t, row, minX, maxX);
    // The fragment routines write the span's pixels through raw pointers: it never leaves the area.
    MYGL_INVARIANT(span.begin > span.end || (minX <= span.begin && span.end <= maxX));
    return span;
}

bool edgeValuesFit32(const RasterTriangle& t, const PixelRect& area) {
    constexpr std::int64_t kStepLimit = std::int64_t{1} << 25, kValueLimit = std::int64_t{1} << 29;
    const int width = area.maxX - area.minX + 1, height = area.maxY - area.minY + 1;
    for (const EdgeFunction& edge : t.edges) {
        if (std::abs(edge.stepX) >= kStepLimit || std::abs(edge.stepY) >= kStepLimit) return false;
        const std::int64_t corner = edge.at(area.minX, area.minY);
        const std::int64_t acrossX = edge.stepX * (width - 1), acrossY = edge.stepY * (height - 1);
        for (const std::int64_t value : {corner, corner + acrossX, corner + acrossY, corner + acrossX + acrossY}) {
            if (std::abs(value) >= kValueLimit) return false;
        }
    }
    return true;
}

void rasterizeTallArea(const RasterTriangle& t, const PixelRect& area, Framebuffer& fb, FragmentCounts& counts,
                       const FragmentRoutine& routine) {
    // The edge functions are linear: if the four corners of the area are inside an edge, all of
    // it is; if they are all outside one edge, none of it is. A tile a large triangle covers
    // whole then needs no span search, and one it misses needs nothing.
    bool coveredWhole = true;
    for (const EdgeFunction& edge : t.edges) {
        const std::int64_t corners[4] = {edge.at(area.minX, area.minY), edge.at(area.maxX, area.minY),
                                         edge.at(area.minX, area.maxY), edge.at(area.maxX, area.maxY)};
        if (corners[0] < 0 && corners[1] < 0 && corners[2] < 0 && corners[3] < 0) return;
        if ((corners[0] | corners[1] | corners[2] | corners[3]) < 0) coveredWhole = false;
    }
    routine.rows(t, area, coveredWhole, fb, counts);
}

}  // namespace glrenderer
