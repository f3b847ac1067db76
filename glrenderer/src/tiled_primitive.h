#pragma once
// Points, lines and smooth primitives' triangles queued for the tiles beside the triangles.
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "fragment_inputs.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/invariant.h"
#include "pixel_rect.h"

namespace glrenderer {

// A primitive other than a filled triangle, drawn in every tile its bounds meet, in submission
// order with the triangles there (so a line drawn over a triangle lands after it), by the
// thread drawing that tile.
class TiledPrimitive {
public:
    PixelRect bounds;  // the pixels it may cover, inside the drawable rectangle
    float meanDepth;   // its place under the painter's sort (a demo method for triangles)

    // Draws its pixels inside `tile`.
    virtual void draw(const PixelRect& tile, Framebuffer& framebuffer, FragmentCounts& counts) const = 0;

protected:
    TiledPrimitive(const PixelRect& pixels, float depth) : bounds(pixels), meanDepth(depth) {}
    ~TiledPrimitive() = default;
};

// Where points and lines go: their records are made in place in the queue's memory, which
// stays until everything queued is drawn (so a record may point to another, e.g. a draw's
// FragmentChoice), then queued.
class PrimitiveQueue {
public:
    // Records are dropped without their destructors: only types that have nothing to destroy.
    template <class T, class... Args>
    T& make(Args&&... args) {
        static_assert(std::is_trivially_destructible_v<T>);
        static_assert(sizeof(T) <= kMaxRecordBytes && alignof(T) <= kMaxRecordAlignment);
        return *new (allocate(sizeof(T), alignof(T))) T(std::forward<Args>(args)...);
    }
    virtual void queue(const TiledPrimitive& primitive) = 0;

    // The largest record, and alignment, the memory behind a queue must take.
    static constexpr std::size_t kMaxRecordBytes = 64 * 1024, kMaxRecordAlignment = 64;

protected:
    ~PrimitiveQueue() = default;
    virtual void* allocate(std::size_t bytes, std::size_t alignment) = 0;
};

// The memory of queued records: blocks that never move, all given back at once; steady state
// allocates nothing.
class RecordPool {
public:
    void* allocate(std::size_t bytes, std::size_t alignment) {
        MYGL_INVARIANT(bytes <= kBlockBytes && alignment <= PrimitiveQueue::kMaxRecordAlignment);
        std::size_t offset = (used_ + alignment - 1) & ~(alignment - 1);
        if (block_ == blocks_.size() || offset + bytes > kBlockBytes) {
            if (block_ < blocks_.size()) ++block_;
            if (block_ == blocks_.size()) blocks_.push_back(std::make_unique<Block>());
            offset = 0;
        }
        used_ = offset + bytes;
        return blocks_[block_]->bytes + offset;
    }
    void reset() { block_ = 0, used_ = 0; }

private:
    static constexpr std::size_t kBlockBytes = PrimitiveQueue::kMaxRecordBytes;  // far more than any record
    struct Block {
        alignas(PrimitiveQueue::kMaxRecordAlignment) std::byte bytes[kBlockBytes];
    };
    std::vector<std::unique_ptr<Block>> blocks_;
    std::size_t block_ = 0, used_ = 0;
};

}  // namespace glrenderer
