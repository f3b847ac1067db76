#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "glrenderer/bitmap.h"
#include "glrenderer/draw_state.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/feedback.h"
#include "glrenderer/hit_range.h"
#include "glrenderer/immediate_buffer.h"
#include "glrenderer/lighting.h"
#include "glrenderer/pixel_image.h"
#include "glrenderer/methods.h"
#include "glrenderer/state_interner.h"
#include "glrenderer/stats.h"
#include "glrenderer/vertex.h"
#include "glrenderer/append_array.h"

namespace glrenderer {

// What glClear writes: the buffers cleared with their values (colour and depth converted by the
// caller's rules, see color_convert.h), the colour and stencil bits written, the scissor box.
struct ClearRequest {
    bool color = false, depth = false, stencil = false;
    std::uint32_t rgba = 0, depth24 = 0;
    std::uint32_t colorMask = 0xFFFFFFFF;
    std::uint8_t stencilValue = 0, stencilMask = 0xFF;
    ScissorBox scissor;
};

class BatchDrawer;
class BatchThread;
class LightingPool;
struct BatchChunk;
struct BatchEntry;

// Turns primitives into pixels of a Framebuffer.
//
// Consecutive submissions of the same mergeable mode (points, lines, triangles, quads) form one
// batch until endBatch(), as the reference's vertex buffer merges glBegin/glEnd blocks: whether
// any vertex of the batch needs clipping decides how quads are split, so the batch matters.
// Batches are collected in chunks and drawn on a thread of the pipeline's own while the caller
// goes on, and triangles are queued and rasterized in screen tiles by worker threads: pixels
// and counters are only promised after finish(). Call finish() before resizing the framebuffer.
class Pipeline {
public:
    explicit Pipeline(Framebuffer& framebuffer);
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    // A primitive (a glBegin/glEnd block): begun, given its vertices one by one, ended. A chunk
    // of batches goes to the batch thread once it holds kPartVertices vertices, and a long
    // primitive of independent filled triangles is cut into parts of that size to go too.
    static constexpr std::size_t kPartVertices = 3072;
    void beginPrimitive(const StateRef& state, PrimitiveMode mode, QuadSplit quadSplit);
    // `state` as the pipeline draws with it, as an interned object for beginPrimitive (see
    // StateInterner): a caller keeps it until its state changes.
    StateRef intern(const DrawState& state);
    // Whether vertices are to be written with streaming stores (writeVertex): a batch thread reads them.
    bool streamsVertices() const { return thread_ != nullptr; }
    // A new vertex of the open primitive, to be filled in place, whole (it is not initialized).
    [[gnu::always_inline]] Vertex& addVertex() {
        if (cuttable_ && openCount() == kPartVertices) [[unlikely]]
            handOverPart();
        if (buffer_.full()) [[unlikely]]
            wrapBuffer();
        buffer_.addVertex();
        ++submitted_.vertices;
        return vertices_->append();
    }
    void endPrimitive();
    // glDrawElements' independent triangles, when acceptsIndexedParts(): the open primitive
    // takes them in parts of at most kPartVertices indices, each a batch of its own with its own
    // vertices (the elements between its smallest and largest index, filled in place, whole,
    // by the caller: they are not initialized) and its indices into them, so that a vertex the part shares is staged
    // once. The reference draws such a draw from its arrays, not through its immediate-mode buffer.
    struct IndexedPart {
        std::span<Vertex> vertices;
        std::span<std::uint32_t> indices;
    };
    static bool acceptsIndexedParts(const DrawState& state, PrimitiveMode mode);
    // Between the calls, primitives are glDrawArrays or glDrawElements draws, which the
    // reference does not pass through its immediate-mode buffer (see ImmediateBuffer).
    void drawFromArrays(bool fromArrays) { buffer_.setFromArrays(fromArrays); }
    // Whether the last draw (or the pending one) had texture coordinates per vertex.
    bool drawsTexCoords() const { return buffer_.drawsTexCoords(); }
    // Whether the vertex format holds a colour (else the reference's vertices take the current one as a constant).
    bool colorInFormat() const { return buffer_.has(VertexAttribute::Color); }
    IndexedPart addIndexedPart(std::size_t vertexCount, std::size_t indexCount);
    // glColor inside glBegin/glEnd. The reference's vertex buffer then gains a color per vertex
    // until its draw ends, and what it held before is drawn as a draw of its own (it decides
    // how flat quads are split).
    void colorPerVertex() {
        if (!colorsPerVertex_) startColorsPerVertex();
    }
    // All three for a whole primitive whose vertices carry their own colors.
    void submit(const StateRef& state, PrimitiveMode mode, std::span<const Vertex> vertices);
    // glVertex, glColor, glNormal, glTexCoord or glEdgeFlag, in or outside glBegin/glEnd, with
    // the attribute's size as the reference stores it: where the reference's vertex format
    // grows, it draws what it holds (see ImmediateBuffer).
    void attribute(VertexAttribute attribute, int size) {
        if (buffer_.widens(attribute, size)) widen(attribute, size);
    }

    // The matrices of the vertices submitted after the call, outside primitives. A batch is
    // transformed with one set: a change ends it.
    void setTransform(const VertexTransform& transform);

    // The lighting of the vertices submitted after the call, outside primitives: the pipeline's
    // vertex stage lights them (their colour is the current colour, unclamped). A change ends the batch.
    void setLighting(const VertexLighting& lighting);
    void setUnlit();
    // glMaterial inside glBegin/glEnd: the open batch's vertices so far are lit now, on the
    // caller's thread, with the batch's lighting; the caller lights the primitive's next ones,
    // each with the outputs outputsOfLastVertex() gives, until endPrimitive().
    void lightOpenBatch();
    LightingOutputs& outputsOfLastVertex();

    // A state change, glFlush: the batch ends, as the reference draws what it holds.
    void endBatch();
    void finish();

    // Draws a bitmap's fragments with the depth test and colour conversion of `state`, after
    // everything submitted before it. Bitmaps outside the framebuffer are cut to it.
    void drawBitmap(const DrawState& state, const Bitmap& bitmap);
    // Draws a glDrawPixels image's fragments likewise (see PixelImage for which pixels).
    void drawPixels(const DrawState& state, const PixelImage& image);

    // Whole colour and depth buffers are cleared tile by tile at the next flush; a clear cut by
    // the scissor or masked, and the stencil buffer, at once.
    void clear(const ClearRequest& request);
    // Whole colour and depth buffers.
    void clear(bool color, std::uint32_t rgba, bool depth, std::uint32_t depth24) {
        ClearRequest request;
        request.color = color, request.depth = depth, request.rgba = rgba, request.depth24 = depth24;
        clear(request);
    }

    // Takes effect for primitives submitted after the call.
    void setMethods(const Methods& methods) {
        closeBatch();
        methods_ = methods;
    }
    const Methods& methods() const { return methods_; }

    // The hits of what was submitted with DrawState::selection since the last call, drawn first.
    HitRange takeHits();
    // The primitives of what was submitted with DrawState::feedback since the last call, in order.
    FeedbackPrimitives takeFeedback();

    // Complete after finish().
    Stats stats() const;
    // Draws what was submitted (it is counted before the reset), then zeroes the counters.
    void resetStats();

private:
    // Draws everything submitted, leaving a clear with nothing drawn after it pending: clears in
    // a row then cost one pass over the framebuffer (a frame usually clears color and depth to
    // one value, then color to another).
    void drawSubmitted();
    // Moves the open primitive's first `count` vertices into the batch.
    void keepOpenVertices(std::size_t count) { openFirst_ += count; }
    std::size_t openCount() const { return vertices_->size() - openFirst_; }
    // Ends the batch (not a flush of the reference's buffer: a cut of our own).
    void closeBatch();
    // Ends the batch in the middle of a primitive, keeping whether it has colors per vertex.
    void closeBatchInPrimitive();
    void handOverPart();
    void startColorsPerVertex();
    // The reference's buffer is full (or its vertex format grows) inside glBegin/glEnd: the
    // batch is drawn with the open primitive's part so far, which goes on with the vertices the
    // reference copies. Returns their number.
    std::size_t wrapOpenPrimitive();
    void wrapBuffer();
    void widen(VertexAttribute attribute, int size);
    void handOverChunk();
    std::size_t batchSize() const;
    // The chunk's lighting outputs as many as its vertices (see litByCaller_).
    void syncOutputs();
    // `state` with flat shading (see BatchChunk::batch).
    StateRef flatVersion(const StateRef& state);

    // Counted as the program submits (vertices, primitives); the batch thread counts the rest on
    // a cache line of its own.
    Stats submitted_;
    Methods methods_;
    StateInterner states_;
    std::pair<StateRef, StateRef> lastFlatVersion_;  // a state and its flat version
    std::unique_ptr<BatchChunk> chunk_;              // being filled on the caller's thread
    std::unique_ptr<BatchEntry> batch_;              // the batch being merged: the end of chunk_
    // chunk_'s vertices: the batches' kept ones, then from openFirst_ the open primitive's,
    // staged in place (kept by moving openFirst_ on; moved to the next chunk if the chunk goes
    // over with a primitive still open).
    AppendArray<Vertex>* vertices_;
    std::size_t openFirst_ = 0;
    AppendArray<Vertex> moved_;                  // the open vertices on their way to the next chunk
    AppendArray<LightingOutputs> movedOutputs_;  // theirs, when litByCaller_
    // The open primitive's vertices are lit by the caller (lightOpenBatch): their lighting
    // outputs follow them wherever the vertices move.
    bool litByCaller_ = false;
    bool cuttable_ = false;         // the open primitive goes over in parts
    bool colorsPerVertex_ = false;  // batch_->colorsPerVertex, tested inline by each glColor
    bool insidePrimitive_ = false;
    bool loopContinued_ = false;  // the open GL_LINE_LOOP wrapped: its first open vertex is the loop's first
    ImmediateBuffer buffer_;      // where the reference's buffer wraps and flushes
    std::unique_ptr<LightingPool> lightings_;  // what batches' `lighting` points to
    std::unique_ptr<BatchDrawer> drawer_;
    std::unique_ptr<BatchThread> thread_;  // null when the pipeline runs on one thread
};

}  // namespace glrenderer
