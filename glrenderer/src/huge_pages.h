#pragma once
#include <cstddef>

namespace glrenderer {

// Memory the pipeline reads in scattered order (the framebuffer a tile at a time, the triangle
// records a tile's bin at a time), in 2 MiB pages where the kernel grants them: in 4 KiB pages
// over half of drawInOrder's samples in bench-mesh were page walks for its records' prefetches.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

// `bytes` aligned to `alignment`, released with std::free. From half a huge page up, the size is
// rounded up to whole huge pages on a huge-page boundary and advised to be huge pages (a hint:
// without them the memory still works); smaller sizes are not worth a page's waste.
// Throws std::bad_alloc.
void* allocatePages(std::size_t bytes, std::size_t alignment);

}  // namespace glrenderer
