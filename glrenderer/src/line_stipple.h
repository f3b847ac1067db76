#pragma once
#include <cstdint>

#include "glrenderer/stipple.h"
#include "window_vertex.h"

namespace glrenderer {

// The reference's line stipple (its draw module's stipple stage, after clipping): a line is cut
// into the pieces where the pattern is on, each drawn as a line of its own. A counter of pixels
// runs along the lines, measured on the major axis (max(|dx|, |dy|)); the n-th pixel from a
// line's start is on when bit ((counter + n) / factor) & 15 is, and the counter then grows by
// the line's length rounded up (measured: newer Mesa's unrounded growth differs on strips). Pieces start and end at
// whole pixels from the line's start, their ends' attributes interpolated linearly in the window (x, y, z, 1 / w,
// colour, fog and texture coordinates alike). The counter restarts at each segment of GL_LINES, at the first segment of
// a strip or loop that survives clipping, at each polygon drawn as lines, and at any point or filled triangle the stage
// sees; it lives as long as the pipeline.
class LineStippler {
public:
    void restart() { counter_ = 0; }

    // Calls draw(a, b) for each piece of start -> end the pattern keeps. A smooth line (the
    // reference's "rectangular" line) is measured along itself, sqrt(dx^2 + dy^2).
    template <class Draw>
    void cut(const LineStipple& stipple, const WindowVertex& start, const WindowVertex& end, bool smooth, Draw&& draw) {
        const float length = smooth ? euclideanLength(start, end) : majorLength(start, end);
        const int whole = wholePixels(length);
        bool on = false;
        int pieceStart = 0;
        for (int i = 0; i < whole; ++i) {
            const bool bit =
                ((stipple.pattern >> (((counter_ + static_cast<std::uint32_t>(i)) / stipple.factor) & 15u)) & 1u) != 0;
            if (bit == on) continue;
            if (on)
                piece(start, end, static_cast<float>(pieceStart) / length, static_cast<float>(i) / length, draw);
            else
                pieceStart = i;
            on = bit;
        }
        if (on && static_cast<float>(pieceStart) < length)
            piece(start, end, static_cast<float>(pieceStart) / length, 1.0f, draw);
        counter_ += static_cast<std::uint32_t>(whole);
    }

private:
    static float majorLength(const WindowVertex& a, const WindowVertex& b);
    static float euclideanLength(const WindowVertex& a, const WindowVertex& b);
    // ceil(length); 0 when it is not finite or beyond any line the rasterizer draws.
    static int wholePixels(float length);
    // The vertex at `t` from a to b.
    static WindowVertex interpolate(const WindowVertex& a, const WindowVertex& b, float t);

    template <class Draw>
    static void piece(const WindowVertex& start, const WindowVertex& end, float t0, float t1, Draw& draw) {
        draw(t0 > 0.0f ? interpolate(start, end, t0) : start, t1 < 1.0f ? interpolate(start, end, t1) : end);
    }

    std::uint32_t counter_ = 0;  // wraps, never overflows
};

}  // namespace glrenderer
