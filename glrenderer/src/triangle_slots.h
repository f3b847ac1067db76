#pragma once
#include <cstddef>
#include <vector>

#include "raster_triangle.h"

namespace glrenderer {

// Where set-up triangles go: a slot to prepare the next one in place, and keep() if it is to be
// drawn (an unkept slot is offered again).
class TriangleTarget {
public:
    virtual RasterTriangle& slot() = 0;
    virtual void keep() = 0;

protected:
    ~TriangleTarget() = default;
};

// Triangles in slots reused from frame to frame: preparing one writes what its state reads over
// whatever the slot held (clearing 200 bytes first was a tenth of a dense mesh's setup), and
// steady state allocates nothing.
class TriangleSlots final : public TriangleTarget {
public:
    RasterTriangle& slot() override {
        if (count_ == slots_.size()) slots_.emplace_back();
        return slots_[count_];
    }
    void keep() override { ++count_; }

    std::size_t size() const { return count_; }
    const RasterTriangle& operator[](std::size_t index) const { return slots_[index]; }
    void clear() { count_ = 0; }
    // Room for `count` triangles, so that filling them allocates nothing.
    void reserve(std::size_t count) { slots_.reserve(count); }

private:
    std::vector<RasterTriangle> slots_;  // the first count_ are kept, the rest spare
    std::size_t count_ = 0;
};

}  // namespace glrenderer
