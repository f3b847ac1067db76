#pragma once
#include <glm/vec4.hpp>

#include "glrenderer/draw_state.h"
#include "clip_vertex.h"

namespace glrenderer {

// A vertex after perspective division and the viewport transform, in the reference's internal
// orientation: y grows downwards from the top row (OSMesa renders y-down and flips on readback).
struct WindowVertex {
    float x = 0, y = 0, z = 0;
    float invW = 1;  // 1 / w_clip, the perspective weight of the attributes
    glm::vec4 color;
    // Only with DrawState::secondaryColors; under flat shading every vertex of a primitive
    // carries its provoking vertex's (the flat primary colour goes apart, as a word).
    glm::vec3 secondaryColor{0.0f};
    float fogCoord = 0;                          // only with fog
    glm::vec4 texCoord{0.0f, 0.0f, 0.0f, 1.0f};  // only with texturing
};

// glViewport and glDepthRange as a scale and an offset per axis, computed in float as the
// reference computes them, with the y axis flipped into the internal orientation.
class ViewportTransform {
public:
    ViewportTransform(const DrawState& state, int framebufferHeight);

    // A vertex from the program: x_window = fma(x_clip * (1 / w), scale, translate), as the
    // reference's vertex stage computes it (one rounding for the multiply-add).
    WindowVertex apply(const glm::vec4& clipPosition, const glm::vec4& color) const;
    WindowVertex apply(const ClipVertex& vertex) const {
        WindowVertex out = apply(vertex.position, vertex.color);
        out.secondaryColor = vertex.secondaryColor;
        out.fogCoord = vertex.fogCoord;
        out.texCoord = vertex.texCoord;
        return out;
    }
    // A vertex made by clipping: the same formula with a separate multiply and add, as the
    // reference's clipper computes it.
    WindowVertex applyToClipped(const ClipVertex& vertex) const;

    float scaleX() const { return scaleX_; }
    float scaleY() const { return scaleY_; }
    float scaleZ() const { return scaleZ_; }
    float translateX() const { return translateX_; }
    float translateY() const { return translateY_; }
    float translateZ() const { return translateZ_; }

private:
    float scaleX_, scaleY_, scaleZ_;
    float translateX_, translateY_, translateZ_;
};

}  // namespace glrenderer
