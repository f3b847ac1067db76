#include "triangle_arena.h"

#include <algorithm>

namespace glrenderer {

RasterTriangle* TriangleArena::takeBlock() {
    std::lock_guard lock(mutex_);
    if (taken_ == blocks_.size()) blocks_.push_back(std::make_unique<RasterTriangle[]>(kBlockTriangles));
    return blocks_[taken_++].get();
}

void TriangleArena::writerDone(std::size_t triangles) {
    std::lock_guard lock(mutex_);
    kept_ += triangles;
}

void TriangleArena::reset() {
    std::lock_guard lock(mutex_);
    const std::size_t enough = std::max(taken_, (kept_ + kBlockTriangles - 1) / kBlockTriangles + 1);
    while (blocks_.size() < enough) blocks_.push_back(std::make_unique<RasterTriangle[]>(kBlockTriangles));
    taken_ = 0;
    kept_ = 0;
}

}  // namespace glrenderer
