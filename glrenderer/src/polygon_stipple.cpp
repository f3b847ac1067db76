#include <algorithm>
#include <deque>
#include <mutex>

#include "glrenderer/stipple.h"

namespace glrenderer {

const PolygonStipplePattern* internPolygonStipple(const PolygonStipplePattern& pattern) {
    if (std::ranges::all_of(pattern, [](std::uint32_t row) { return row == 0xFFFFFFFFu; })) return nullptr;
    static std::mutex mutex;
    static std::deque<PolygonStipplePattern> kept;  // a deque never moves what it holds
    const std::scoped_lock lock(mutex);
    const auto found = std::ranges::find(kept, pattern);
    if (found != kept.end()) return &*found;
    return &kept.emplace_back(pattern);
}

}  // namespace glrenderer
