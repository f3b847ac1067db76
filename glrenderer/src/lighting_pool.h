#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "glrenderer/lighting.h"

namespace glrenderer {

// Copies of the prepared lighting that submitted batches point to (BatchHeader::lighting): each
// lives until the pipeline has drawn everything submitted (release()). Released slots are
// reused, so a steady frame allocates nothing.
class LightingPool {
public:
    // More than this many lightings between two draws of everything: the pipeline draws first.
    static constexpr std::size_t kCapacity = 4096;

    bool full() const { return used_ == kCapacity; }
    const VertexLighting* keep(const VertexLighting& lighting) {
        if (used_ == slots_.size()) slots_.push_back(std::make_unique<VertexLighting>());
        *slots_[used_] = lighting;
        return slots_[used_++].get();
    }
    void release() { used_ = 0; }

private:
    std::vector<std::unique_ptr<VertexLighting>> slots_;
    std::size_t used_ = 0;
};

}  // namespace glrenderer
