#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "glrenderer/draw_state.h"
#include "glrenderer/methods.h"
#include "glrenderer/vertex.h"

namespace glrenderer {

// What a draw is, as the reference sees it: consecutive submissions of one mode under one
// state, merged, with the methods in force when they were submitted.
struct BatchHeader {
    DrawState state;
    Methods methods;
    PrimitiveMode mode = PrimitiveMode::Points;
    bool colorsPerVertex = false;  // glColor was called inside its glBegin/glEnd blocks
};

// One draw with its vertices.
struct Batch : BatchHeader {
    std::span<const Vertex> vertices;
};

// A batch's place in its chunk.
struct BatchEntry : BatchHeader {
    std::size_t first = 0, count = 0;  // its vertices in the chunk
};

// Consecutive batches with their vertices in one array: what the pipeline hands to its batch
// thread at once, so that a thousand small draws cost one hand-over. Chunks are reused frame
// after frame, keeping their capacity.
struct BatchChunk {
    BatchChunk(std::size_t vertexCapacity, std::size_t batchCapacity) {
        vertices.reserve(vertexCapacity);
        batches.reserve(batchCapacity);
    }

    std::vector<Vertex> vertices;
    std::vector<BatchEntry> batches;

    Batch batch(const BatchEntry& entry) const {
        return {entry, std::span<const Vertex>(vertices).subspan(entry.first, entry.count)};
    }
    void clear() {
        vertices.clear();
        batches.clear();
    }
};

}  // namespace glrenderer
