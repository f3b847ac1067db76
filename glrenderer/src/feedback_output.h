#pragma once
// Window vertices into feedback primitives (glrenderer/feedback.h).
#include "glrenderer/feedback.h"
#include "window_vertex.h"

namespace glrenderer {

class FeedbackOutput {
public:
    // `lineResetPending` outlives the output: the reference's feedback stage keeps its flag from
    // one draw to the next.
    FeedbackOutput(FeedbackPrimitives& primitives, bool& lineResetPending, int framebufferHeight)
        : primitives_(primitives),
          lineResetPending_(lineResetPending),
          height_(static_cast<float>(framebufferHeight)) {}

    void point(const WindowVertex& v) { add(FeedbackPrimitive::Kind::Point, {convert(v)}); }
    // The next line is a GL_LINE_RESET_TOKEN (only the unfilled stage restarts the stipple).
    void resetLineStipple() { lineResetPending_ = true; }
    void line(const WindowVertex& a, const WindowVertex& b) {
        add(lineResetPending_ ? FeedbackPrimitive::Kind::LineReset : FeedbackPrimitive::Kind::Line,
            {convert(a), convert(b)});
        lineResetPending_ = false;
    }
    void triangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c) {
        add(FeedbackPrimitive::Kind::Polygon, {convert(a), convert(b), convert(c)});
    }

private:
    // The reference flips y back from its top-down window (height - y) and answers 1 / (1 / w).
    FeedbackVertex convert(const WindowVertex& v) const { return {v.x, height_ - v.y, v.z, 1.0f / v.invW, v.color}; }
    void add(FeedbackPrimitive::Kind kind, const std::array<FeedbackVertex, 3>& vertices) {
        primitives_.push_back({kind, vertices});
    }

    FeedbackPrimitives& primitives_;
    bool& lineResetPending_;
    float height_;
};

}  // namespace glrenderer
