#pragma once
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "huge_pages.h"
#include "raster_triangle.h"

namespace glrenderer {

// The bytes of a triangle record that every key's setup writes and its tiles read (RasterTriangle's
// first fields, up to the fog coordinate's plane): its first three cache lines.
inline constexpr std::size_t kCommonTriangleBytes =
    offsetof(RasterTriangle, fragment) + offsetof(FragmentInputs, fogCoord);
static_assert(kCommonTriangleBytes <= 3 * 64);

// The bytes of a triangle record that the fast path of `key` reads: the common ones, and those of
// the stipple pattern, the secondary colour, the fog and the texture after them where the key has
// them. (The routine of any key reads its key after the common ones too.)
constexpr std::size_t triangleBytesRead(const FragmentKey& key) {
    constexpr std::size_t inputs = offsetof(RasterTriangle, fragment);
    if (key.texturesColor()) return inputs + offsetof(FragmentInputs, textureBorderColor) + sizeof(glm::vec4);
    if (key.fog != FogMode::Off) return inputs + offsetof(FragmentInputs, fog) + sizeof(FogState);
    if (key.colorSum) return inputs + offsetof(FragmentInputs, fog);
    if (key.polygonStipple) return inputs + offsetof(FragmentInputs, secondaryColor);
    return kCommonTriangleBytes;
}

// Fetches a record's first `count` bytes into the cache, ahead of drawing it.
inline void prefetchTriangle(const RasterTriangle& triangle, std::size_t count) {
    const char* bytes = reinterpret_cast<const char*>(&triangle);
    for (std::size_t line = 0; line < count; line += 64) __builtin_prefetch(bytes + line);
}
// The lines every triangle uses: fetching the rest too read lines that most keys never touch,
// a third of a dense mesh's triangle records.
inline void prefetchCommonLines(const RasterTriangle& triangle) { prefetchTriangle(triangle, kCommonTriangleBytes); }

// How many triangles ahead of drawing a tile's records are fetched: a tile's triangles lie
// scattered over the queue, usually far out of cache.
inline constexpr std::size_t kFetchAhead = 4;
// The same where tiny triangles are packed (FragmentRoutine::packed): further, as packing one
// takes less time than its block took.
inline constexpr std::size_t kPackedFetchAhead = 24;

// Where set-up triangles go: a slot to prepare the next one in place, and keep() if it is to be
// drawn (an unkept slot is offered again).
class TriangleTarget {
public:
    virtual RasterTriangle& slot() = 0;
    virtual void keep() = 0;

protected:
    ~TriangleTarget() = default;
};

// The slots of the triangles queued for the tiles: blocks that never move (the tile bins point
// into them), taken by whichever thread sets triangles up, and all given back at once when
// everything queued is drawn. Slots are reused: preparing a triangle writes what its state
// reads over whatever the slot held (clearing 200 bytes first was a tenth of a dense mesh's
// setup), and steady state allocates nothing.
class TriangleArena {
public:
    // A block fills one huge page.
    static constexpr std::size_t kBlockBytes = kHugePageBytes;
    static constexpr std::size_t kBlockTriangles = kBlockBytes / sizeof(RasterTriangle);

    // A block of kBlockTriangles slots, the taker's until reset(); any thread.
    RasterTriangle* takeBlock();
    // A writer is done until the reset: it kept `triangles` in its blocks.
    void writerDone(std::size_t triangles);
    // Every block is free again: nothing may point into them any more. Keeps enough blocks for
    // as many triangles however two writers share them (each may leave a block part full), so
    // that doing the same again allocates nothing whatever the timing.
    void reset();

private:
    std::mutex mutex_;
    // Blocks from allocatePages (huge_pages.h): the tiles read their records in scattered order.
    struct BlockDeleter {
        void operator()(RasterTriangle* block) const;
    };
    using TriangleBlock = std::unique_ptr<RasterTriangle[], BlockDeleter>;
    static TriangleBlock allocateBlock();

    std::vector<TriangleBlock> blocks_;
    std::size_t taken_ = 0;
    std::size_t kept_ = 0;  // triangles, reported by the writers done
};

// Fills arena blocks one slot after the other, for one thread.
class ArenaWriter final : public TriangleTarget {
public:
    explicit ArenaWriter(TriangleArena& arena) : arena_(arena) {}

    RasterTriangle& slot() override {
        if (used_ == TriangleArena::kBlockTriangles) {
            block_ = arena_.takeBlock();
            used_ = 0;
        }
        // A slot a few ahead fetched for its writing: a frame's records are far more than the
        // caches hold, and setup otherwise waited for each line it stored into.
        if (used_ + kWriteAhead < TriangleArena::kBlockTriangles) {
            const char* ahead = reinterpret_cast<const char*>(&block_[used_ + kWriteAhead]);
            for (std::size_t line = 0; line < kCommonTriangleBytes; line += 64) __builtin_prefetch(ahead + line, 1);
        }
        return block_[used_];
    }
    void keep() override {
        ++used_;
        ++kept_;
    }
    const RasterTriangle& last() const { return block_[used_ - 1]; }
    // Before the arena's reset(): its block is no longer this writer's.
    void release() {
        arena_.writerDone(kept_);
        block_ = nullptr;
        used_ = TriangleArena::kBlockTriangles;
        kept_ = 0;
    }

private:
    static constexpr std::size_t kWriteAhead = 4;

    TriangleArena& arena_;
    RasterTriangle* block_ = nullptr;
    std::size_t used_ = TriangleArena::kBlockTriangles;
    std::size_t kept_ = 0;  // since the last release
};

}  // namespace glrenderer
