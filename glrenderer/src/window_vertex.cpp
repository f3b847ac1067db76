#include "window_vertex.h"

#include <cmath>

namespace glrenderer {

ViewportTransform::ViewportTransform(const DrawState& state, int framebufferHeight) {
    const Viewport& vp = state.viewport;
    const float halfWidth = static_cast<float>(vp.width) * 0.5f;
    const float halfHeight = static_cast<float>(vp.height) * 0.5f;
    scaleX_ = halfWidth;
    translateX_ = halfWidth + static_cast<float>(vp.x);
    // y flips: internal y = H - y_gl.
    scaleY_ = -halfHeight;
    translateY_ = static_cast<float>(framebufferHeight) - (halfHeight + static_cast<float>(vp.y));
    scaleZ_ = state.depthScale();
    translateZ_ = state.depthTranslate();
}

WindowVertex ViewportTransform::apply(const glm::vec4& p, const glm::vec4& color) const {
    WindowVertex out;
    out.invW = 1.0f / p.w;
    out.x = std::fma(p.x * out.invW, scaleX_, translateX_);
    out.y = std::fma(p.y * out.invW, scaleY_, translateY_);
    out.z = std::fma(p.z * out.invW, scaleZ_, translateZ_);
    out.color = color;
    return out;
}

WindowVertex ViewportTransform::applyToClipped(const ClipVertex& vertex) const {
    const glm::vec4& p = vertex.position;
    WindowVertex out;
    out.invW = 1.0f / p.w;
    out.x = p.x * out.invW * scaleX_ + translateX_;
    out.y = p.y * out.invW * scaleY_ + translateY_;
    out.z = p.z * out.invW * scaleZ_ + translateZ_;
    out.color = vertex.color;
    out.secondaryColor = vertex.secondaryColor;
    out.fogCoord = vertex.fogCoord;
    out.texCoord = vertex.texCoord;
    return out;
}

}  // namespace glrenderer
