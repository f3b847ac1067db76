#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "glrenderer/framebuffer.h"
#include "glrenderer/stats.h"
#include "tiled_primitive.h"
#include "triangle_arena.h"
#include "worker_pool.h"

namespace glrenderer {

// Defers rasterization: triangles, points and lines are binned into screen tiles and drawn at
// flush(), tiles in parallel, each tile's primitives in submission order; drawSomeTiles() may
// draw part of the queue earlier on a thread that would otherwise wait. Where textured triangles
// cover a tile many times over, their colour is deferred (drawDeferred): each pixel is shaded
// once, by the fragment that wins it. Every pixel is computed exactly as the immediate kernel
// computes it, so the result does not depend on tiling, deferral, threads or timing.
class TileRasterizer final : public TriangleTarget, public PrimitiveQueue {
public:
    explicit TileRasterizer(Framebuffer& framebuffer);

    // A triangle is prepared in slot() and queued by keep(), binned into the tiles it may cover.
    RasterTriangle& slot() override {
        fitTilesToFramebuffer();
        return writer_.slot();
    }
    void keep() override {
        writer_.keep();
        bin(writer_.last());
    }
    // A point, a line or a smooth primitive's triangle, made with make().
    void queue(const TiledPrimitive& primitive) override;
    // Queues triangles set up elsewhere in arena() slots, in order.
    void queue(std::span<const RasterTriangle* const> triangles);
    // Where triangles are set up for queue(). Its slots stay taken until releaseTriangles().
    TriangleArena& arena() { return arena_; }
    // Once everything queued is drawn and every other writer of the arena released: the
    // arena's slots are free for what comes next.
    void releaseTriangles();
    // Clears the buffers before the tiles are next drawn, each tile just before its triangles
    // while it is in cache, instead of one pass over the whole framebuffer now. A tile that still
    // holds the same clear values (nothing drawn there since) is not written again.
    void clearAtFlush(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24);
    // Draws everything queued and every pending clear; adds fragment counts to stats. The
    // framebuffer must keep its size between queuing and flush(); if it changed, the queued
    // triangles are dropped. With paintersSort each tile draws its triangles far to near by
    // mean depth instead of in order.
    void flush(Stats& stats, bool paintersSort = false);
    // Draws the tiles that hold queued triangles, on the calling thread alone, one after the
    // other until stop() returns true; flush() draws the rest. Not for the painter's sort, which
    // orders a tile's whole queue.
    template <class Stop>
    void drawSomeTiles(Stats& stats, Stop&& stop) {
        FragmentCounts counts;
        startDrawingTiles();
        for (std::size_t tile = 0; tile < bins_.size(); ++tile) {
            if (stop()) return addFragmentCounts(stats, counts);
            if (!bins_[tile].empty()) drawTile(tile, counts, false);
        }
        queued_ = 0;  // every bin is empty
        addFragmentCounts(stats, counts);
    }
    std::size_t queued() const { return queued_; }

private:
    // A tile's queued primitive: a triangle, or another (bit 0 set: records are aligned).
    class BinEntry {
    public:
        // `defersColor`: the triangle's routine has deferred shading's passes, kept here so that
        // finding a tile's runs reads no record (a pass over them stalled a mesh's tiles).
        // `packs`: its routine packs tiny triangles (FragmentRoutine::packed), likewise.
        BinEntry(const RasterTriangle* triangle, bool defersColor, bool packs)
            : bits_(reinterpret_cast<std::uintptr_t>(triangle) | (defersColor ? kDefers : 0) | (packs ? kPacks : 0)) {}
        explicit BinEntry(const TiledPrimitive* other) : bits_(reinterpret_cast<std::uintptr_t>(other) | kOther) {}
        BinEntry() = default;  // a free place in a bin's storage
        const RasterTriangle* triangle() const {
            return bits_ & kOther ? nullptr : reinterpret_cast<const RasterTriangle*>(bits_ & ~(kDefers | kPacks));
        }
        const TiledPrimitive& other() const { return *reinterpret_cast<const TiledPrimitive*>(bits_ & ~kOther); }
        bool defersColor() const { return (bits_ & kDefers) != 0; }
        bool packs() const { return (bits_ & kPacks) != 0; }
        float meanDepth() const { return triangle() ? triangle()->meanDepth() : other().meanDepth; }

    private:
        static constexpr std::uintptr_t kOther = 1, kDefers = 2, kPacks = 4;
        std::uintptr_t bits_ = kOther;
    };

    // A tile's queued entries, in submission order. The storage only grows: adding where it has
    // room is a store, inline and without a call, so that keep()'s common path saves no registers
    // (std::vector::push_back's growth path made every triangle's keep() save six).
    class TileBin {
    public:
        bool hasRoom() const { return count_ < storage_.size(); }
        void addWithRoom(BinEntry entry) {
            storage_[count_++] = entry;
            ++addedSinceFlush_;
        }
        void add(BinEntry entry) {
            if (!hasRoom()) storage_.resize(std::max<std::size_t>(2 * storage_.size(), 16));
            addWithRoom(entry);
        }
        std::span<BinEntry> entries() { return {storage_.data(), count_}; }
        bool empty() const { return count_ == 0; }
        void clear() { count_ = 0; }
        // At a flush: room for as many entries as were added since the last one, however many
        // were drawn early (which depends on timing), so that steady state allocates nothing.
        void makeRoomForNextFlush() {
            if (storage_.size() < addedSinceFlush_) storage_.resize(addedSinceFlush_);
            addedSinceFlush_ = 0;
        }

    private:
        std::vector<BinEntry> storage_;
        std::size_t count_ = 0, addedSinceFlush_ = 0;
    };

    void* allocate(std::size_t bytes, std::size_t alignment) override { return records_.allocate(bytes, alignment); }
    // No tile is known to hold its clear values any more.
    void forgetClearedTiles() { std::fill(holdsClear_.begin(), holdsClear_.end(), std::uint8_t{0}); }
    // Tiles are 2^tileShift_ pixels square, chosen per framebuffer size in refitTiles().
    int tileSize() const { return 1 << tileShift_; }
    void fitTilesToFramebuffer() {
        if (binnedWidth_ != framebuffer_.width() || binnedHeight_ != framebuffer_.height()) refitTiles();
    }
    void refitTiles();
    std::size_t tileAt(int tx, int ty) const {
        return static_cast<std::size_t>(ty) * static_cast<std::size_t>(tilesX_) + static_cast<std::size_t>(tx);
    }
    // Adds a kept triangle to the bins of the tiles its bounds touch. Inline for most of a mesh's
    // triangles, in one tile whose bin has room and not deferring their colour; the rest out of
    // line (binSpread), whose stack frame every triangle paid when all of it was.
    void bin(const RasterTriangle& triangle) {
        ++queued_;
        const int shift = tileShift_;
        const int firstX = triangle.minX >> shift, lastX = triangle.maxX >> shift;
        const int firstY = triangle.minY >> shift, lastY = triangle.maxY >> shift;
        const bool exact = triangle.method == RasterMethod::Exact;
        const FragmentRoutine& routine = *triangle.fragment.routine;
        const BinEntry entry(&triangle, exact && routine.shade, exact && routine.packed);
        if (firstX == lastX && firstY == lastY && !entry.defersColor()) [[likely]] {
            TileBin& bin = bins_[tileAt(firstX, firstY)];
            if (bin.hasRoom()) [[likely]]
                return bin.addWithRoom(entry);
        }
        binSpread(triangle, entry);
    }
    // bin() for the other triangles: each tile's bin, and where the colour is deferred, the
    // triangle's cover of each tile. (Two arguments: a tail call from bin().)
    [[gnu::noinline]] void binSpread(const RasterTriangle& triangle, BinEntry entry);
    // Adds `entry` to the bins of the tiles from (firstX, firstY) to (lastX, lastY).
    void binInto(BinEntry entry, int firstX, int lastX, int firstY, int lastY);
    // Clears the tile if a clear is pending for it, draws its queued triangles, empties its bin.
    void drawTile(std::size_t tile, FragmentCounts& counts, bool paintersSort);
    // Draws the entries of a tile, one after the other.
    void drawInOrder(std::span<const BinEntry> entries, const PixelRect& rect, FragmentCounts& counts);
    // Draws a run of triangles that defer their colour with deferred shading (DeferredPass).
    void drawDeferred(std::span<const BinEntry> run, const PixelRect& rect, FragmentCounts& counts);
    // Before tiles are drawn: which tiles hold the pending clear's values already.
    void startDrawingTiles();
    // Clears the tile's part of the buffers being cleared that do not hold the values already;
    // `drawnNext` if triangles follow.
    void clearTile(std::size_t tile, const PixelRect& rect, bool drawnNext);

    struct PendingClear {
        bool color = false, depth = false;
        std::uint32_t rgba = 0, depth24 = 0;
    };

    struct alignas(64) ThreadCounts {  // one cache line per thread
        FragmentCounts counts;
    };

    Framebuffer& framebuffer_;
    WorkerPool pool_;
    std::vector<ThreadCounts> threadCounts_;
    PendingClear clear_;
    std::vector<std::uint8_t> clearPending_;  // per tile: not yet cleared by clear_
    // Per tile, the buffers whose pixels there still hold heldRgba_ / heldDepth24_, the values
    // of their last clear carried out: most of a sparse scene's tiles are background, and
    // clearing them again was most of its frame at 1080p. Valid while the framebuffer's
    // writeGeneration() is heldGeneration_.
    static constexpr std::uint8_t kHoldsColor = 1, kHoldsDepth = 2;
    std::vector<std::uint8_t> holdsClear_;
    std::uint32_t heldRgba_ = 0, heldDepth24_ = 0;
    std::uint64_t heldGeneration_ = 0;
    TriangleArena arena_;
    ArenaWriter writer_{arena_};  // for slot() and keep()
    RecordPool records_;          // of the queued points and lines
    std::size_t queued_ = 0;      // binned and not drawn yet
    std::vector<TileBin> bins_;   // per tile
    // Per tile, the pixels of the bounds of the triangles queued there that defer their colour.
    std::vector<std::int64_t> deferringCover_;
    int tileShift_ = 7;
    int tilesX_ = 0, tilesY_ = 0;
    int binnedWidth_ = 0, binnedHeight_ = 0;
};

}  // namespace glrenderer
