#include "tile_rasterizer.h"

#include "glrenderer/invariant.h"
#include "raster_float_methods.h"
#include "raster_span.h"
#include "thread_count.h"
#include "tile_columns.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace glrenderer {
namespace {

// Below this many queued triangles, or pixels to clear, the threads cost more than they save.
constexpr std::size_t kParallelThreshold = 64;
constexpr std::size_t kParallelClearPixels = 64 * 1024;

// Tile sizes, as powers of two: the largest of 64, 128 and 256 pixels that cuts the framebuffer
// into at least 64 tiles. Bigger tiles cost less per triangle (fewer triangles cross a border
// and are visited twice, fewer bin entries), but the threads, each keeping to its end of the
// tiles, need enough of them to share the work evenly. Measured with the tiles kept per thread,
// against 128 and 256: 640x480 with 64 (80 tiles) has the torus 6% and the gears 20% faster,
// 1920x1080 with 128 (135 tiles) the torus 4% and the fill 5% faster, the rest equal or better.
constexpr int kMinTileShift = 6, kMaxTileShift = 8;
static_assert((1 << kMinTileShift) % kTileColumns == 0, "a tile holds whole groups of columns (tile_columns.h)");
constexpr int kMinTiles = 64;

int tilesAlong(int pixels, int shift) { return (pixels + (1 << shift) - 1) >> shift; }

// Fills pixels with one value. A tile that no triangle draws is not read again soon: streaming
// stores write it without first reading each line into the cache (half the memory traffic,
// and clearing is most of the frame of a sparse scene at 1080p).
void fillPixels(std::uint32_t* pixels, std::size_t count, std::uint32_t value, bool stream) {
#if defined(__x86_64__)
    if (stream) {
        std::size_t i = 0;
        for (; i < count && reinterpret_cast<std::uintptr_t>(pixels + i) % 16 != 0; ++i) pixels[i] = value;
        const __m128i four = _mm_set1_epi32(static_cast<int>(value));
        for (; i + 4 <= count; i += 4) _mm_stream_si128(reinterpret_cast<__m128i*>(pixels + i), four);
        std::fill_n(pixels + i, count - i, value);
        return;
    }
#endif
    std::fill_n(pixels, count, value);
}

// Streaming stores are not ordered with the stores that publish the tile's completion.
void finishStreaming() {
#if defined(__x86_64__)
    _mm_sfence();
#endif
}

// The tile's entries in order, each triangle's record fetched a few ahead.
template <class Entry, class Draw>
void forEachFetchingAhead(std::span<const Entry> entries, Draw&& draw) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (i + kFetchAhead < entries.size()) {
            if (const RasterTriangle* ahead = entries[i + kFetchAhead].triangle()) prefetchCommonLines(*ahead);
        }
        draw(entries[i]);
    }
}

// The longest run of triangles drawInOrder passes to a routine that packs them.
constexpr std::size_t kPackedRun = 32;

// Deferred shading pays where the triangles that defer their colour cover a tile this many
// times over, counting their bounds (about twice their area).
constexpr std::int64_t kDeferredMinCover = 4;

}  // namespace

TileRasterizer::TileRasterizer(Framebuffer& framebuffer)
    : framebuffer_(framebuffer), pool_(workerThreadCount()), threadCounts_(pool_.threadCount()) {}

void TileRasterizer::refitTiles() {
    binnedWidth_ = framebuffer_.width();
    binnedHeight_ = framebuffer_.height();
    tileShift_ = kMaxTileShift;
    while (tileShift_ > kMinTileShift &&
           tilesAlong(binnedWidth_, tileShift_) * tilesAlong(binnedHeight_, tileShift_) < kMinTiles) {
        --tileShift_;
    }
    tilesX_ = tilesAlong(binnedWidth_, tileShift_);
    tilesY_ = tilesAlong(binnedHeight_, tileShift_);
    const auto tiles = static_cast<std::size_t>(tilesX_) * static_cast<std::size_t>(tilesY_);
    queued_ = 0;  // queued for a framebuffer of another size
    bins_.assign(tiles, TileBin());
    deferringCover_.assign(tiles, 0);
    clearPending_.assign(tiles, clear_.color || clear_.depth);
    holdsClear_.assign(tiles, 0);
}

void TileRasterizer::queue(std::span<const RasterTriangle* const> triangles) {
    fitTilesToFramebuffer();
    // Set up on another thread, their bounds are in that core's cache: fetched a few ahead, the
    // load does not stall each bin() (half of its samples in a mesh waited on it).
    constexpr std::size_t kAhead = 8;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        if (i + kAhead < triangles.size()) __builtin_prefetch(&triangles[i + kAhead]->minX);
        bin(*triangles[i]);
    }
}

void TileRasterizer::releaseTriangles() {
    writer_.release();
    arena_.reset();
    records_.reset();
}

void TileRasterizer::queue(const TiledPrimitive& primitive) {
    fitTilesToFramebuffer();
    const PixelRect& r = primitive.bounds;
    MYGL_INVARIANT(r.minX >= 0 && r.minX <= r.maxX && r.maxX < binnedWidth_ && r.minY >= 0 && r.minY <= r.maxY &&
                   r.maxY < binnedHeight_);
    ++queued_;
    const int shift = tileShift_;
    binInto(BinEntry(&primitive), r.minX >> shift, r.maxX >> shift, r.minY >> shift, r.maxY >> shift);
}

void TileRasterizer::binSpread(const RasterTriangle& triangle, BinEntry entry) {
    const int shift = tileShift_;
    const int firstX = triangle.minX >> shift, lastX = triangle.maxX >> shift;
    const int firstY = triangle.minY >> shift, lastY = triangle.maxY >> shift;
    binInto(entry, firstX, lastX, firstY, lastY);
    if (!entry.defersColor()) return;
    // The triangle's bounds in each tile, for drawTile's choice (here, where they are in cache).
    const int size = tileSize();
    for (int ty = firstY; ty <= lastY; ++ty) {
        const int rows = std::min(triangle.maxY, (ty + 1) * size - 1) - std::max(triangle.minY, ty * size) + 1;
        for (int tx = firstX; tx <= lastX; ++tx) {
            const int columns = std::min(triangle.maxX, (tx + 1) * size - 1) - std::max(triangle.minX, tx * size) + 1;
            deferringCover_[tileAt(tx, ty)] += std::int64_t{rows} * columns;
        }
    }
}

void TileRasterizer::binInto(BinEntry entry, int firstX, int lastX, int firstY, int lastY) {
    for (int ty = firstY; ty <= lastY; ++ty) {
        for (int tx = firstX; tx <= lastX; ++tx) bins_[tileAt(tx, ty)].add(entry);
    }
}

void TileRasterizer::clearAtFlush(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24) {
    fitTilesToFramebuffer();
    if (color) clear_.color = true, clear_.rgba = rgba;
    if (depth) clear_.depth = true, clear_.depth24 = depth24;
    std::fill(clearPending_.begin(), clearPending_.end(), std::uint8_t{1});
}

void TileRasterizer::startDrawingTiles() {
    if (heldGeneration_ != framebuffer_.writeGeneration()) {
        forgetClearedTiles();
        heldGeneration_ = framebuffer_.writeGeneration();
    }
    const auto forget = [this](std::uint8_t buffer) {
        for (std::uint8_t& holds : holdsClear_) holds &= static_cast<std::uint8_t>(~buffer);
    };
    if (clear_.color && clear_.rgba != heldRgba_) forget(kHoldsColor), heldRgba_ = clear_.rgba;
    if (clear_.depth && clear_.depth24 != heldDepth24_) forget(kHoldsDepth), heldDepth24_ = clear_.depth24;
}

void TileRasterizer::clearTile(std::size_t tile, const PixelRect& rect, bool drawnNext) {
    const bool color = clear_.color && !(holdsClear_[tile] & kHoldsColor);
    const bool depth = clear_.depth && !(holdsClear_[tile] & kHoldsDepth);
    holdsClear_[tile] |= static_cast<std::uint8_t>((clear_.color ? kHoldsColor : 0) | (clear_.depth ? kHoldsDepth : 0));
    if (!color && !depth) return;
    const std::size_t width = static_cast<std::size_t>(framebuffer_.width());
    const auto count = static_cast<std::size_t>(rect.maxX - rect.minX + 1);
    for (int row = rect.minY; row <= rect.maxY; ++row) {
        const std::size_t begin =
            static_cast<std::size_t>(framebuffer_.height() - 1 - row) * width + static_cast<std::size_t>(rect.minX);
        if (color) fillPixels(framebuffer_.color().data() + begin, count, clear_.rgba, !drawnNext);
        if (depth) fillPixels(framebuffer_.depth().data() + begin, count, clear_.depth24, !drawnNext);
    }
    finishStreaming();
}

void TileRasterizer::drawInOrder(std::span<const BinEntry> entries, const PixelRect& rect, FragmentCounts& counts) {
    std::array<const RasterTriangle*, kPackedRun> run;
    for (std::size_t i = 0; i < entries.size();) {
        if (!entries[i].packs()) {
            if (i + kFetchAhead < entries.size()) {
                if (const RasterTriangle* ahead = entries[i + kFetchAhead].triangle()) prefetchCommonLines(*ahead);
            }
            if (const RasterTriangle* triangle = entries[i].triangle())
                rasterizeWithMethod(*triangle, rect, framebuffer_, counts);
            else
                entries[i].other().draw(rect, framebuffer_, counts);
            ++i;
            continue;
        }
        // Consecutive triangles whose routines pack tiny ones go to them together, up to a run's
        // length. The routines fetch the records
        // ahead as they draw (fetched here, all at once, they stalled on the cache's misses).
        std::size_t length = 0;
        for (; i < entries.size() && entries[i].packs() && length < kPackedRun; ++i) {
            run[length] = entries[i].triangle();
            if (length < kPackedFetchAhead) prefetchCommonLines(*run[length]);
            ++length;
        }
        rasterizePackedRun(std::span(run.data(), length), rect, framebuffer_, counts);
    }
}

void TileRasterizer::drawDeferred(std::span<const BinEntry> run, const PixelRect& rect, FragmentCounts& counts) {
    forEachFetchingAhead(run, [&](const BinEntry& entry) {
        const RasterTriangle& t = *entry.triangle();
        rasterizeTriangleSpans(t, rect, framebuffer_, counts, *t.fragment.routine->visibility);
    });
    // Each pixel's winner is the first fragment to reach its final depth (FragmentKey::defersColor);
    // its shading unmarks the depth, so that no later fragment of that depth takes the pixel.
    FragmentCounts shaded;  // the same fragments again: the visibility pass counted them
    forEachFetchingAhead(run, [&](const BinEntry& entry) {
        const RasterTriangle& t = *entry.triangle();
        rasterizeTriangleSpans(t, rect, framebuffer_, shaded, *t.fragment.routine->shade);
    });
}

void TileRasterizer::drawTile(std::size_t tile, FragmentCounts& counts, bool paintersSort) {
    const int tx = static_cast<int>(tile % static_cast<std::size_t>(tilesX_));
    const int ty = static_cast<int>(tile / static_cast<std::size_t>(tilesX_));
    const int size = tileSize();
    const PixelRect rect{tx * size, std::min((tx + 1) * size, binnedWidth_) - 1, ty * size,
                         std::min((ty + 1) * size, binnedHeight_) - 1};
    // The routines write the areas they cut from the tile through raw pointers.
    MYGL_INVARIANT(rect.maxX < framebuffer_.width() && rect.maxY < framebuffer_.height());
    const std::span<BinEntry> bin = bins_[tile].entries();
    if (paintersSort) {
        std::stable_sort(bin.begin(), bin.end(),
                         [](const BinEntry& a, const BinEntry& b) { return a.meanDepth() > b.meanDepth(); });
    }
    if (clearPending_[tile]) {
        clearTile(tile, rect, !bin.empty());
        clearPending_[tile] = 0;
    }
    if (!bin.empty()) holdsClear_[tile] = 0;
    // Runs of entries: triangles that defer their colour, or others. Deferred shading pays where
    // such triangles cover the tile many times over.
    const std::int64_t tileArea = std::int64_t{rect.maxX - rect.minX + 1} * (rect.maxY - rect.minY + 1);
    const bool deferring = deferringCover_[tile] >= kDeferredMinCover * tileArea;
    deferringCover_[tile] = 0;
    for (std::size_t first = 0; first < bin.size();) {
        const bool defers = bin[first].defersColor();
        std::size_t end = first + 1;
        while (end < bin.size() && bin[end].defersColor() == defers) ++end;
        const std::span<const BinEntry> run = bin.subspan(first, end - first);
        if (defers && deferring)
            drawDeferred(run, rect, counts);
        else
            drawInOrder(run, rect, counts);
        first = end;
    }
    bins_[tile].clear();
}

void TileRasterizer::flush(Stats& stats, bool paintersSort) {
    fitTilesToFramebuffer();
    const bool clearing = clear_.color || clear_.depth;
    if (queued_ == 0 && !clearing) return;
    startDrawingTiles();
    for (ThreadCounts& c : threadCounts_) c.counts = {};
    auto drawAny = [&](std::size_t tile, unsigned thread) {
        drawTile(tile, threadCounts_[thread].counts, paintersSort);
    };
    const std::size_t pixels = static_cast<std::size_t>(binnedWidth_) * static_cast<std::size_t>(binnedHeight_);
    if (queued_ < kParallelThreshold && !(clearing && pixels >= kParallelClearPixels)) {
        for (std::size_t tile = 0; tile < bins_.size(); ++tile) drawAny(tile, 0);
    } else {
        pool_.run(bins_.size(), drawAny);
    }
    for (const ThreadCounts& c : threadCounts_) addFragmentCounts(stats, c.counts);
    queued_ = 0;
    clear_ = {};
    for (TileBin& bin : bins_) bin.makeRoomForNextFlush();
}

}  // namespace glrenderer
