#include "vertex_stage.h"

#include "clip.h"
#include "cpu_features.h"

namespace glrenderer {

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
