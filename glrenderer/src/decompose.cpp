#include "decompose.h"

namespace glrenderer {

bool isTriangleMode(PrimitiveMode mode) { return mode >= PrimitiveMode::Triangles; }

bool fillsThroughDrawModule(const DrawState& state) {
    const PolygonOffset& offset = state.polygonOffset;
    const bool drawModuleOffsets =
        (state.lineStipple.enabled && state.lineStipple.pattern != 0xFFFF) || state.lineSmooth || state.pointSmooth;
    return state.polygonStipple.enabled || ((offset.fill || offset.line || offset.point) && drawModuleOffsets);
}

std::size_t usableVertexCount(PrimitiveMode mode, std::size_t count) {
    switch (mode) {
    case PrimitiveMode::Points: return count;
    case PrimitiveMode::Lines: return count - count % 2;
    case PrimitiveMode::LineLoop:
    case PrimitiveMode::LineStrip: return count >= 2 ? count : 0;
    case PrimitiveMode::Triangles: return count - count % 3;
    case PrimitiveMode::TriangleStrip:
    case PrimitiveMode::TriangleFan:
    case PrimitiveMode::Polygon: return count >= 3 ? count : 0;
    case PrimitiveMode::Quads: return count - count % 4;
    case PrimitiveMode::QuadStrip: return count >= 4 ? count - count % 2 : 0;
    }
    return 0;
}

}  // namespace glrenderer
