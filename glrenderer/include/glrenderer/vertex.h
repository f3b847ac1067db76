#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "glrenderer/matrix.h"

namespace glrenderer {

// A vertex as the program gives it: object-space position, RGBA colour (already clamped to
// [0, 1], as GL clamps a vertex's colour), normal and edge flag (which hides polygon edges in
// line and point mode). The pipeline's vertex stage transforms it with its batch's
// VertexTransform, on the pipeline's side. Lighting replaces the colour in place; its other
// outputs go to a LightingOutputs of their own, only for the batches that read them.
struct Vertex {
    glm::vec4 position;
    glm::vec4 color;
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 texCoord{0.0f, 0.0f, 0.0f, 1.0f};
    bool edgeFlag = true;
};
// Every vertex the program submits is written, then read by the batch thread: a cache line each.
static_assert(sizeof(Vertex) == 64);

// A lit vertex's colours besides its front colour, kept (BatchChunk::lightingOutputs) only for
// batches whose state reads them (needsLightingOutputs).
struct LightingOutputs {
    glm::vec4 backColor{0.0f};  // lit for the back face: with DrawState::twoSidedColors
    // The specular terms, front and back, with DrawState::secondaryColors (no alpha).
    glm::vec3 secondaryColor{0.0f}, backSecondaryColor{0.0f};
};

// The matrices a batch's vertices are transformed with.
struct VertexTransform {
    Matrix modelviewProjection = kIdentity;  // object to clip space
    Matrix modelview = kIdentity;            // object to eye space (for the seeds' culling methods)
    bool operator==(const VertexTransform&) const = default;
};

}  // namespace glrenderer
