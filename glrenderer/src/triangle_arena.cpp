#include "triangle_arena.h"

#include <algorithm>
#include <cstdlib>

namespace glrenderer {

TriangleArena::TriangleBlock TriangleArena::allocateBlock() {
    auto* block = static_cast<RasterTriangle*>(allocatePages(kBlockBytes, alignof(RasterTriangle)));
    std::uninitialized_value_construct_n(block, kBlockTriangles);
    return TriangleBlock(block);
}

void TriangleArena::BlockDeleter::operator()(RasterTriangle* block) const {
    std::destroy_n(block, kBlockTriangles);
    std::free(block);
}

RasterTriangle* TriangleArena::takeBlock() {
    std::lock_guard lock(mutex_);
    if (taken_ == blocks_.size()) blocks_.push_back(allocateBlock());
    return blocks_[taken_++].get();
}

void TriangleArena::writerDone(std::size_t triangles) {
    std::lock_guard lock(mutex_);
    kept_ += triangles;
}

void TriangleArena::reset() {
    std::lock_guard lock(mutex_);
    const std::size_t enough = std::max(taken_, (kept_ + kBlockTriangles - 1) / kBlockTriangles + 1);
    while (blocks_.size() < enough) blocks_.push_back(allocateBlock());
    taken_ = 0;
    kept_ = 0;
}

}  // namespace glrenderer
