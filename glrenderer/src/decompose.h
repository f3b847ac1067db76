#pragma once
#include <cstddef>
#include <cstdint>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// The reference splits quads differently depending on whether the draw goes straight to the
// rasterizer or through its clipping/unfilled "draw module" stages.
enum class DecompositionPath { Direct, DrawModule };

// Indices of one triangle into the primitive's vertices. The provoking vertex (the one whose
// color a flat-shaded triangle takes) is always the last, v[2], as in the reference.
struct TriangleIndices {
    std::uint32_t v[3];
};

// Vertices a mode needs for its first primitive and per further primitive, and the usable count
// (incomplete trailing primitives dropped, as glEnd does). 0 when nothing can be drawn.
std::size_t usableVertexCount(PrimitiveMode mode, std::size_t count);

bool isTriangleMode(PrimitiveMode mode);

// Whether the reference sends filled polygons through its draw module with no vertex to clip:
// polygon stipple on (even the pattern of all ones), or any polygon offset on while the
// rasterizer leaves the offset to the draw module, which it does with line stipple on (a pattern
// other than all ones), smooth lines or smooth points. Measured: docs/probes/quad_split_probe.cpp.
bool fillsThroughDrawModule(const DrawState& state);

// Calls emit(TriangleIndices) for each triangle of a triangle-type mode, in the reference's order.
// v1v3Quads: quads take the v1-v3 diagonal on the direct path too. The reference does so for
// flat shading where the draw's vertices carry colors of their own (glColor inside
// glBegin/glEnd), keeping quads' provoking v3 last in both triangles (with one current color
// for all vertices it splits flat quads like smooth ones, measured on the depth buffer), and
// for quads it has converted into triangles before drawing (QuadSplit::V1V3).
template <class Emit>
void decomposeTriangles(PrimitiveMode mode, std::uint32_t count, DecompositionPath path, bool v1v3Quads, Emit&& emit) {
    switch (mode) {
    case PrimitiveMode::Triangles:
        for (std::uint32_t i = 0; i + 2 < count; i += 3) emit(TriangleIndices{{i, i + 1, i + 2}});
        break;
    case PrimitiveMode::TriangleStrip:
        for (std::uint32_t i = 0; i + 2 < count; ++i) {
            if (i % 2 == 0)
                emit(TriangleIndices{{i, i + 1, i + 2}});
            else
                emit(TriangleIndices{{i + 1, i, i + 2}});
        }
        break;
    case PrimitiveMode::TriangleFan:
        for (std::uint32_t i = 1; i + 1 < count; ++i) emit(TriangleIndices{{0, i, i + 1}});
        break;
    case PrimitiveMode::Quads: {
        // The direct path keeps the v0-v2 diagonal unless told otherwise; the draw module uses
        // the v1-v3 diagonal so that both triangles end on the provoking v3.
        const bool v0v2Diagonal = path == DecompositionPath::Direct && !v1v3Quads;
        for (std::uint32_t i = 0; i + 3 < count; i += 4) {
            if (v0v2Diagonal) {
                emit(TriangleIndices{{i, i + 1, i + 2}});
                emit(TriangleIndices{{i, i + 2, i + 3}});
            } else {
                emit(TriangleIndices{{i, i + 1, i + 3}});
                emit(TriangleIndices{{i + 1, i + 2, i + 3}});
            }
        }
        break;
    }
    case PrimitiveMode::QuadStrip:
        // The same two triangles on both paths, emitted in opposite orders (which shows where a
        // strip folds over itself without the depth test).
        for (std::uint32_t i = 0; i + 3 < count; i += 2) {
            const TriangleIndices first{{i, i + 1, i + 3}}, second{{i + 2, i, i + 3}};
            if (path == DecompositionPath::Direct)
                emit(first), emit(second);
            else
                emit(second), emit(first);
        }
        break;
    case PrimitiveMode::Polygon:
        // A fan around v0 with v0 last: polygons take their flat color from the first vertex.
        for (std::uint32_t i = 1; i + 1 < count; ++i) emit(TriangleIndices{{i, i + 1, 0}});
        break;
    default: break;
    }
}

}  // namespace glrenderer
