#include "tile_rasterizer.h"

#include "raster_float_methods.h"
#include "thread_count.h"

#include <algorithm>

namespace glrenderer {
namespace {

// Below this many queued triangles the threads cost more than they save.
constexpr std::size_t kParallelThreshold = 64;

}  // namespace

TileRasterizer::TileRasterizer(Framebuffer& framebuffer)
    : framebuffer_(framebuffer), pool_(workerThreadCount()),
      threadCounts_(pool_.threadCount()), shader_(bestSpanShader()) {}

void TileRasterizer::resetBins() {
    binnedWidth_ = framebuffer_.width();
    binnedHeight_ = framebuffer_.height();
    tilesX_ = (binnedWidth_ + kTileSize - 1) / kTileSize;
    tilesY_ = (binnedHeight_ + kTileSize - 1) / kTileSize;
    bins_.resize(static_cast<std::size_t>(tilesX_) * static_cast<std::size_t>(tilesY_));
    for (auto& bin : bins_) bin.clear();
}

void TileRasterizer::add(const RasterTriangle& triangle) {
    if (triangles_.empty() || binnedWidth_ != framebuffer_.width() || binnedHeight_ != framebuffer_.height()) {
        resetBins();
    }
    const auto index = static_cast<std::uint32_t>(triangles_.size());
    triangles_.push_back(triangle);
    for (int ty = triangle.minY / kTileSize; ty <= triangle.maxY / kTileSize; ++ty)
        for (int tx = triangle.minX / kTileSize; tx <= triangle.maxX / kTileSize; ++tx)
            bins_[static_cast<std::size_t>(ty * tilesX_ + tx)].push_back(index);
}

void TileRasterizer::flush(Stats& stats, bool paintersSort) {
    if (binnedWidth_ != framebuffer_.width() || binnedHeight_ != framebuffer_.height()) triangles_.clear();
    if (triangles_.empty()) return;
    for (ThreadCounts& c : threadCounts_) c.counts = {};
    auto drawTile = [&](std::size_t tile, unsigned thread) {
        const int tx = static_cast<int>(tile % static_cast<std::size_t>(tilesX_));
        const int ty = static_cast<int>(tile / static_cast<std::size_t>(tilesX_));
        const PixelRect rect{tx * kTileSize, std::min((tx + 1) * kTileSize, binnedWidth_) - 1,
                             ty * kTileSize, std::min((ty + 1) * kTileSize, binnedHeight_) - 1};
        if (paintersSort) {
            std::stable_sort(bins_[tile].begin(), bins_[tile].end(), [this](std::uint32_t a, std::uint32_t b) {
                return triangles_[a].meanDepth > triangles_[b].meanDepth;
            });
        }
        for (std::uint32_t index : bins_[tile])
            rasterizeWithMethod(triangles_[index], rect, framebuffer_, threadCounts_[thread].counts, shader_);
    };
    if (triangles_.size() < kParallelThreshold) {
        for (std::size_t tile = 0; tile < bins_.size(); ++tile) drawTile(tile, 0);
    } else {
        pool_.run(bins_.size(), drawTile);
    }
    for (const ThreadCounts& c : threadCounts_) {
        stats.fragments += c.counts.fragments;
        stats.fragmentsPassed += c.counts.passed;
        stats.pixelsWritten += c.counts.passed;
    }
    triangles_.clear();
}

}  // namespace glrenderer
