#include "huge_pages.h"

#include <sys/mman.h>

#include <cstdlib>
#include <new>

namespace glrenderer {

void* allocatePages(std::size_t bytes, std::size_t alignment) {
    const bool huge = bytes >= kHugePageBytes / 2;
    if (huge) {
        alignment = kHugePageBytes;
        bytes = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
    } else {
        bytes = (bytes + alignment - 1) / alignment * alignment;  // aligned_alloc takes whole multiples
    }
    void* memory = std::aligned_alloc(alignment, bytes);
    if (!memory) throw std::bad_alloc();
    if (huge) madvise(memory, bytes, MADV_HUGEPAGE);
    return memory;
}

}  // namespace glrenderer
