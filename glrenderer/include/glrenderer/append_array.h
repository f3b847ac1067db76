#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>

#include "glrenderer/invariant.h"

namespace glrenderer {

// What the program submits (a chunk's vertices and indices): an array whose appended elements
// are not initialized, since their writer fills each whole (a std::vector's emplace_back and
// resize zeroed a 104-byte vertex first). It keeps its storage: after the first frames,
// appending allocates nothing.
template <class T>
class AppendArray {
public:
    std::size_t size() const { return size_; }
    T* begin() { return storage_.get(); }
    T* end() { return storage_.get() + size_; }
    const T* begin() const { return storage_.get(); }
    const T* end() const { return storage_.get() + size_; }
    T& operator[](std::size_t i) { return storage_[i]; }
    T* data() { return storage_.get(); }
    const T* data() const { return storage_.get(); }
    void reserve(std::size_t capacity) {
        if (capacity > capacity_) grow(capacity);
    }

    // A new last element, for the caller to fill.
    [[gnu::always_inline]] T& append() {
        if (size_ == capacity_) [[unlikely]]
            grow(size_ + 1);
        return storage_[size_++];
    }
    // `count` new last elements, for the caller to fill.
    T* appendUninitialized(std::size_t count) {
        reserve(size_ + count);
        size_ += count;
        return end() - count;
    }
    void append(const T* first, const T* last) {
        std::copy(first, last, appendUninitialized(static_cast<std::size_t>(last - first)));
    }
    void push_back(T element) { append() = element; }  // (a copy: `element` may be one of these)
    void clear() { size_ = 0; }
    // Keeps the first `count` elements.
    void truncate(std::size_t count) {
        MYGL_INVARIANT(count <= size_);
        size_ = std::min(count, size_);
    }
    // Drops `count` elements from `first` on.
    void erase(std::size_t first, std::size_t count) {
        MYGL_INVARIANT(first + count <= size_);
        first = std::min(first, size_), count = std::min(count, size_ - first);
        std::copy(begin() + first + count, end(), begin() + first);
        size_ -= count;
    }
    void assign(const T* first, const T* last) {
        clear();
        append(first, last);
    }

private:
    [[gnu::noinline]] void grow(std::size_t needed) {
        const std::size_t capacity = std::max<std::size_t>({2 * capacity_, needed, 1024});
        auto storage = std::make_unique<T[]>(capacity);
        std::copy(begin(), end(), storage.get());
        storage_ = std::move(storage);
        capacity_ = capacity;
    }

    std::unique_ptr<T[]> storage_;
    std::size_t size_ = 0, capacity_ = 0;
};

}  // namespace glrenderer
