#pragma once
#include <immintrin.h>

#include <array>
#include <cstdint>

#include "raster_triangle.h"

namespace glrenderer {

// Whether a triangle whose pixel bounds hold at most four pixel centers covers none of them:
// a tenth of a dense mesh's triangles have such bounds and cover nothing, and dropping them
// before their planes saves their record, bin entry and fragment routine call. Branch-free: the
// bounds' shape picks lanes from a table, and bounds of more centers never count as empty.
//
// The edge functions at the centers go in float lanes: bounds at most four centers across put
// every vertex within five pixels of the others, so the steps are below 2^19 and the values at
// those centers below 2^23 in magnitude, whole numbers that float holds exactly (and whose sum
// is never -0, so the sign bit is the sign).
class PixelCenterTest {
public:
    // `edges` over the centers [minX, maxX] x [minY, maxY] (not empty): true if none is inside
    // all three and there are at most four of them. (Out of line: inlined, its registers made
    // the rest of prepareTriangle spill, which cost every triangle what the test saves.)
    [[gnu::noinline]] static bool coversNone(const EdgeFunction (&edges)[3], std::int64_t minX, std::int64_t maxX,
                                             std::int64_t minY, std::int64_t maxY) {
        const auto clampedSpan = [](std::int64_t first, std::int64_t last) {
            const auto span = static_cast<std::uint64_t>(last - first);  // centers - 1
            return span < kSpans ? span : kSpans - 1;
        };
        const Shape& shape = shapes()[clampedSpan(minY, maxY) * kSpans + clampedSpan(minX, maxX)];
        const __m128 dx = _mm_load_ps(shape.dx), dy = _mm_load_ps(shape.dy);
        const auto lanes = [&](const EdgeFunction& edge) {
            const auto value = static_cast<float>(edge.at(minX, minY));
            const auto stepX = static_cast<float>(edge.stepX), stepY = static_cast<float>(edge.stepY);
            return _mm_add_ps(_mm_add_ps(_mm_set1_ps(value), _mm_mul_ps(dx, _mm_set1_ps(stepX))),
                              _mm_mul_ps(dy, _mm_set1_ps(stepY)));
        };
        // Sign bit set where a center is outside an edge.
        const __m128 outside = _mm_or_ps(_mm_or_ps(lanes(edges[0]), lanes(edges[1])), lanes(edges[2]));
        const auto outsideBits = static_cast<unsigned>(_mm_movemask_ps(outside));
        return (outsideBits & shape.centers) == shape.centers;
    }

private:
    // Spans of 1 to 4 centers, and 5 for more.
    static constexpr std::uint64_t kSpans = 5;
    // Lane i is center (dx, dy) from the bounds' first; `centers` has a bit per lane in the
    // bounds, or kNever for bounds of more than four centers.
    struct alignas(16) Shape {
        float dx[4], dy[4];
        unsigned centers;
    };
    static constexpr unsigned kNever = 1u << 4;  // a bit no movemask sets: never all outside

    static constexpr std::array<Shape, kSpans * kSpans> makeShapes() {
        std::array<Shape, kSpans * kSpans> table{};
        for (unsigned rows = 1; rows <= kSpans; ++rows) {
            for (unsigned columns = 1; columns <= kSpans; ++columns) {
                Shape& shape = table[(rows - 1) * kSpans + (columns - 1)];
                const unsigned count = rows * columns;
                shape.centers = count <= 4 ? (1u << count) - 1 : kNever;
                for (unsigned i = 0; i < 4; ++i) {
                    shape.dx[i] = shape.centers == kNever ? 0.0f : static_cast<float>(i % columns);
                    shape.dy[i] = shape.centers == kNever ? 0.0f : static_cast<float>(i / columns);
                }
            }
        }
        return table;
    }
    static const std::array<Shape, kSpans * kSpans>& shapes() {
        static constexpr std::array<Shape, kSpans* kSpans> kShapes = makeShapes();
        return kShapes;
    }
};

}  // namespace glrenderer
