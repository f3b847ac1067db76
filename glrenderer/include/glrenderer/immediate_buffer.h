#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "glrenderer/draw_state.h"

namespace glrenderer {

// The attributes a glBegin/glEnd vertex can carry, each with its size in floats as the
// reference stores it: position 2-4 (glVertex2/3/4), color 3 (glColor3f) or 4 (glColor4*, and
// glColor3 of other types, which the reference passes on as glColor4f), normal 3, texture
// coordinate 2, edge flag 1.
enum class VertexAttribute : std::uint8_t { Position, Color, Normal, TexCoord, EdgeFlag };
inline constexpr std::size_t kVertexAttributeCount = 5;

// The bookkeeping of the reference's immediate-mode vertex buffer (Mesa's vbo_exec), which
// decides where a long run of glBegin/glEnd vertices is cut into separate draws. Vertices are
// stored whole, in a format of the attributes used since the last flush (floats each), in a
// 512 KiB buffer object that flushes use up from the front: a draw takes the bytes written
// since the previous one, and a new buffer starts only when no more than 1 KiB is left. When
// the vertices since the last flush reach (bytes left / vertex size) - 1, the reference draws
// them and continues the open primitive in the rest of the buffer (a "wrap"). Only counts are
// kept here; the Pipeline moves the vertices.
class ImmediateBuffer {
public:
    static constexpr std::size_t kBufferBytes = 512 * 1024;
    static constexpr std::size_t kMinFreeBytes = 1024;
    // Blocks that could not be merged into one draw: the buffer is drawn at this many.
    static constexpr std::size_t kMaxPrimitives = 64;

    bool widens(VertexAttribute attribute, int size) const { return size > sizes_[index(attribute)]; }
    // An attribute used at a size larger than the format has: the pending vertices are drawn
    // (`carried` of them, the open primitive's, copied to the next part) and the format widens.
    void widen(VertexAttribute attribute, int size, bool insideBeginEnd, std::size_t carried);

    // glBegin: attributes set since the last flush without a vertex are not kept in the format.
    void beginPrimitive();
    // Whether the next vertex must go to a new part of the buffer: the last one filled it.
    // (Vertices given without a format, by Pipeline::submit, never fill it.)
    bool full() const { return vertices_ >= fullAt_; }
    // glDrawArrays and glDrawElements, while set: the reference draws them from the arrays, not
    // through this buffer, so their vertices neither fill it nor use up its room.
    void setFromArrays(bool fromArrays) {
        fromArrays_ = fromArrays;
        updateFullAt();
    }
    void addVertex() { ++vertices_; }
    // The full buffer is drawn; the open primitive goes on with `carried` vertices copied.
    void wrap(std::size_t carried);
    // glEnd of a block of `count` vertices in this part of the buffer, drawn as `mode`.
    // `loopClosed`: a GL_LINE_LOOP that wrapped, whose first vertex is stored again at the end.
    // True when the reference then draws what it holds (too many blocks it could not merge).
    bool endPrimitive(PrimitiveMode mode, std::size_t count, bool loopClosed);

    bool hasVertices() const { return vertices_ > 0; }
    bool has(VertexAttribute attribute) const { return sizes_[index(attribute)] > 0; }
    // Whether the reference's last draw, or the one pending, had texture coordinates in its
    // vertex format (its fragment program then reads them as varying: glBitmap's).
    bool drawsTexCoords() const { return vertices_ > 0 ? has(VertexAttribute::TexCoord) : lastDrawTexCoords_; }
    // Draws what the buffer holds.
    void flush();
    // A state change, glFlush, glClear, a read: the vertices are drawn and the format forgotten.
    void flushAndReset();

private:
    static std::size_t index(VertexAttribute attribute) { return static_cast<std::size_t>(attribute); }
    void resetFormat();
    void updateMaxVertices();
    // (One comparison for each glVertex.)
    void updateFullAt() {
        fullAt_ = fromArrays_ || maxVertices_ == 0 ? std::numeric_limits<std::size_t>::max() : maxVertices_;
    }

    std::array<int, kVertexAttributeCount> sizes_{};
    std::size_t vertexFloats_ = 0;
    std::size_t usedBytes_ = 0;                                     // by earlier draws, in the current buffer object
    std::size_t vertices_ = 0;                                      // since the last draw
    std::size_t maxVertices_ = 0;                                   // 0 until the format has an attribute
    std::size_t fullAt_ = std::numeric_limits<std::size_t>::max();  // vertices_ that make it full()
    std::size_t primitives_ = 0;  // blocks since the last draw, merged ones counted once
    // The previous block of this draw, which the next one may merge with.
    PrimitiveMode lastMode_ = PrimitiveMode::Points;
    bool lastMergeable_ = false;
    bool fromArrays_ = false;
    bool lastDrawTexCoords_ = false;
};

// Which of the open primitive's `count` vertices (in this part of the buffer) the reference
// draws at a wrap, and which it copies to the next part to continue the primitive.
struct WrapSplit {
    std::size_t drawnFirst = 0, drawnCount = 0;
    std::array<std::uint32_t, 3> carried{};
    std::size_t carriedCount = 0;
};
// `continuedLoop`: a GL_LINE_LOOP already wrapped before; its part starts with a copy of the
// loop's first vertex, which is not drawn until the loop ends.
WrapSplit splitAtWrap(PrimitiveMode mode, std::size_t count, bool continuedLoop);

}  // namespace glrenderer
