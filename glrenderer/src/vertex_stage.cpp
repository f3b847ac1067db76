#include "vertex_stage.h"

#include "clip.h"

namespace glrenderer {

bool cpuHasFma() {
#if defined(__x86_64__) || defined(__i386__)
    static const bool has = __builtin_cpu_supports("fma") && __builtin_cpu_supports("sse4.1");
    return has;
#else
    return false;
#endif
}

std::uint8_t transformVertices(std::span<const Vertex> vertices, const ViewportTransform& viewport,
                               std::uint8_t* outcodes, WindowVertex* windowVertices) {
    if (cpuHasFma()) return transformVerticesFma(vertices, viewport, outcodes, windowVertices);
    std::uint8_t anyOutside = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        outcodes[i] = clipOutcode(vertices[i].position);
        anyOutside |= outcodes[i];
        windowVertices[i] = viewport.apply(vertices[i]);
    }
    return anyOutside;
}

}  // namespace glrenderer
