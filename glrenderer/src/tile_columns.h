#pragma once

namespace glrenderer {

// While tiles are drawn in parallel, each by one thread, a tile is at least kTileColumns pixels
// wide and starts at a multiple of it (tile_rasterizer.cpp asserts it). A block of `count`
// pixels of a row from x that lies in one such group of columns and ends inside the row is then
// touched by no other thread: a routine may load it whole and store it whole, the lanes it does
// not draw merged back unchanged, instead of a masked store (several times slower than a plain
// one on AMD's Zen CPUs: the torus 7-10% faster in 8 lanes of AVX2 on Zen 3).
constexpr int kTileColumns = 64;

constexpr bool blockInOneTile(int x, int count, int rowWidth) {
    return x >= 0 && x / kTileColumns == (x + count - 1) / kTileColumns && x + count <= rowWidth;
}

}  // namespace glrenderer
