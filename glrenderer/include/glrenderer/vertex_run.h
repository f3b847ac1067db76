#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>

#include "glrenderer/invariant.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

// Vertices as the program submits them (the open primitive's, a chunk's): an array whose
// appended elements are not initialized, since their writer fills each whole (a std::vector's
// emplace_back and resize zeroed the 104 bytes first). It keeps its storage: after the first
// frames, appending allocates nothing.
class VertexRun {
public:
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    Vertex* begin() { return storage_.get(); }
    Vertex* end() { return storage_.get() + size_; }
    const Vertex* begin() const { return storage_.get(); }
    const Vertex* end() const { return storage_.get() + size_; }
    Vertex& operator[](std::size_t i) { return storage_[i]; }
    Vertex& front() { return storage_[0]; }
    Vertex* data() { return storage_.get(); }
    const Vertex* data() const { return storage_.get(); }
    void reserve(std::size_t capacity) {
        if (capacity > capacity_) grow(capacity);
    }

    // A new last vertex, for the caller to fill.
    [[gnu::always_inline]] Vertex& append() {
        if (size_ == capacity_) [[unlikely]]
            grow(size_ + 1);
        return storage_[size_++];
    }
    // `count` new last vertices, for the caller to fill.
    Vertex* appendUninitialized(std::size_t count) {
        reserve(size_ + count);
        size_ += count;
        return end() - count;
    }
    void append(const Vertex* first, const Vertex* last) {
        std::copy(first, last, appendUninitialized(static_cast<std::size_t>(last - first)));
    }
    void push_back(Vertex vertex) { append() = vertex; }  // (a copy: `vertex` may be one of these)
    void clear() { size_ = 0; }
    // Keeps the first `count` vertices.
    void truncate(std::size_t count) {
        MYGL_INVARIANT(count <= size_);
        size_ = std::min(count, size_);
    }
    // Drops the first `count` vertices.
    void eraseFront(std::size_t count) {
        MYGL_INVARIANT(count <= size_);
        count = std::min(count, size_);
        std::copy(begin() + count, end(), begin());
        size_ -= count;
    }
    void assign(const Vertex* first, const Vertex* last) {
        clear();
        append(first, last);
    }

private:
    [[gnu::noinline]] void grow(std::size_t needed) {
        const std::size_t capacity = std::max<std::size_t>({2 * capacity_, needed, 1024});
        auto storage = std::make_unique<Vertex[]>(capacity);
        std::copy(begin(), end(), storage.get());
        storage_ = std::move(storage);
        capacity_ = capacity;
    }

    std::unique_ptr<Vertex[]> storage_;
    std::size_t size_ = 0, capacity_ = 0;
};

}  // namespace glrenderer
