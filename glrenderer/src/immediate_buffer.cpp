// The rules of Mesa 22.3's src/mesa/vbo: vbo_exec_api.c (vbo_exec_wrap_buffers, vbo_exec_vtx_wrap,
// vbo_exec_wrap_upgrade_vertex, _mesa_Begin/_mesa_End, vbo_exec_FlushVertices_internal),
// vbo_exec_draw.c (vbo_exec_vtx_flush, vbo_exec_buffer_has_space), vbo_private.h
// (vbo_compute_max_verts), vbo_exec.c (vbo_merge_draws, vbo_copy_vertices); confirmed against OSMesa by
// tests/api/test_vertex_buffer_wrap.cpp.
#include "glrenderer/immediate_buffer.h"

#include <algorithm>

namespace glrenderer {
namespace {

// Whether a block of `count` vertices of `mode` can have the next block of its mode merged in.
bool endsWhole(PrimitiveMode mode, std::size_t count) {
    switch (mode) {
    case PrimitiveMode::Points: return true;
    case PrimitiveMode::Lines: return count % 2 == 0;
    case PrimitiveMode::Triangles: return count % 3 == 0;
    case PrimitiveMode::Quads: return count % 4 == 0;
    default: return false;
    }
}

}  // namespace

void ImmediateBuffer::widen(VertexAttribute attribute, int size, bool insideBeginEnd, std::size_t carried) {
    const std::size_t lastCount = vertices_;
    if (vertices_ > 0 && primitives_ > 0) flush();
    vertices_ = 0;
    primitives_ = insideBeginEnd ? 1 : 0;
    int& current = sizes_[index(attribute)];
    // An attribute new to the format, set between blocks after more than 8 vertices: the format
    // starts again from it alone, so that it does not widen the vertices of later blocks.
    if (!insideBeginEnd && current == 0 && lastCount > 8 && vertexFloats_ > 0) resetFormat();
    vertexFloats_ += static_cast<std::size_t>(size - current);
    current = size;
    updateMaxVertices();
    vertices_ = carried;
}

void ImmediateBuffer::beginPrimitive() {
    if (vertexFloats_ > 0 && sizes_[index(VertexAttribute::Position)] == 0) flushAndReset();
    ++primitives_;
}

void ImmediateBuffer::wrap(std::size_t carried) {
    flush();
    primitives_ = 1;
    vertices_ = carried;
}

bool ImmediateBuffer::endPrimitive(PrimitiveMode mode, std::size_t count, bool loopClosed) {
    if (loopClosed) ++vertices_;
    // The block joins the previous one of its mode when that is a mode of independent
    // primitives and ended with a whole one.
    if (primitives_ >= 2 && lastMergeable_ && mode == lastMode_) --primitives_;
    lastMode_ = mode;
    lastMergeable_ = endsWhole(mode, count);
    return primitives_ == kMaxPrimitives;
}

void ImmediateBuffer::flush() {
    if (vertices_ > 0) lastDrawTexCoords_ = has(VertexAttribute::TexCoord);
    if (!fromArrays_) usedBytes_ += vertices_ * vertexFloats_ * sizeof(float);
    if (kBufferBytes <= usedBytes_ + kMinFreeBytes) usedBytes_ = 0;  // a new buffer object
    updateMaxVertices();
    vertices_ = 0;
    primitives_ = 0;
}

void ImmediateBuffer::flushAndReset() {
    if (vertices_ > 0) flush();
    resetFormat();
}

void ImmediateBuffer::resetFormat() {
    sizes_ = {};
    vertexFloats_ = 0;
}

void ImmediateBuffer::updateMaxVertices() {
    if (vertexFloats_ == 0) return;  // the reference keeps its count until an attribute comes
    // One vertex is kept free for the copy of a line loop's first vertex at glEnd.
    const std::size_t fit = (kBufferBytes - usedBytes_) / (vertexFloats_ * sizeof(float));
    maxVertices_ = fit > 0 ? fit - 1 : 0;
    updateFullAt();
}

WrapSplit splitAtWrap(PrimitiveMode mode, std::size_t count, bool continuedLoop) {
    WrapSplit split;
    split.drawnCount = count;
    const auto carryLast = [&](std::size_t n) {
        n = std::min(n, count);
        for (std::size_t i = 0; i < n; ++i) split.carried[i] = static_cast<std::uint32_t>(count - n + i);
        split.carriedCount = n;
    };
    switch (mode) {
    case PrimitiveMode::Points: break;
    case PrimitiveMode::Lines: carryLast(count % 2), split.drawnCount -= count % 2; break;
    case PrimitiveMode::Triangles: carryLast(count % 3), split.drawnCount -= count % 3; break;
    case PrimitiveMode::Quads: carryLast(count % 4), split.drawnCount -= count % 4; break;
    case PrimitiveMode::LineStrip: carryLast(1); break;
    case PrimitiveMode::TriangleStrip:
        // An even number of triangles is drawn, so that the next part keeps their facing.
        split.drawnCount -= count % 2;
        carryLast(count <= 1 ? count : 2 + count % 2);
        break;
    case PrimitiveMode::QuadStrip: carryLast(count <= 1 ? count : 2 + count % 2); break;
    case PrimitiveMode::LineLoop:
        // Drawn as a line strip; a continued part's first vertex is the loop's first, kept for
        // the closing segment at glEnd.
        if (continuedLoop) split.drawnFirst = 1, split.drawnCount = count - 1;
        [[fallthrough]];
    case PrimitiveMode::TriangleFan:
    case PrimitiveMode::Polygon:
        // The first vertex and the last.
        split.carried = {0, static_cast<std::uint32_t>(count > 0 ? count - 1 : 0), 0};
        split.carriedCount = std::min<std::size_t>(count, 2);
        break;
    }
    return split;
}

}  // namespace glrenderer
