#include "glrenderer/pipeline.h"

#include "batch.h"
#include "batch_drawer.h"
#include "batch_thread.h"
#include "decompose.h"
#include "denormals_are_zero.h"
#include "glrenderer/immediate_buffer.h"
#include "glrenderer/invariant.h"
#include "lighting_pool.h"
#include "thread_count.h"

namespace glrenderer {
namespace {

// Modes whose consecutive glBegin/glEnd blocks the reference merges into one draw.
bool isMergeable(PrimitiveMode mode) {
    return mode == PrimitiveMode::Points || mode == PrimitiveMode::Lines || mode == PrimitiveMode::Triangles ||
           mode == PrimitiveMode::Quads;
}

// Filled independent triangles come out the same however a batch of them is cut, so a long
// batch is drawn in parts while the program goes on. (Quads are not: the batch as a whole
// decides their diagonal.)
bool canCut(const BatchHeader& batch) {
    return batch.mode == PrimitiveMode::Triangles && batch.state->polygonFront == PolygonMode::Fill &&
           batch.state->polygonBack == PolygonMode::Fill;
}

// Chunks in circulation with a batch thread: one being filled, the others queued or drawn.
// Each is made big enough for a usual hand-over (a part, plus the batch that crossed it), so
// that steady state allocates nothing; 4 of them are 2.1 MB (64-byte vertices). With more in
// flight, the program's thread would set fewer up itself when the batch thread is behind (8
// measured 2-3% slower).
constexpr std::size_t kChunks = 4;
constexpr std::size_t kChunkBatches = 256;

// The reference's state tracker gives a culled face the other face's polygon mode (Mesa
// st_atom_rasterizer.c, "simplify when culling is active"): with the culled face's mode LINE or
// POINT and the other FILL, the draw is a filled one (its path, its quads' diagonal, its culling).
DrawState withCulledFaceModes(DrawState state) {
    if (!state.cullEnabled) return state;
    if (state.cullFace != Face::Back) state.polygonFront = state.polygonBack;
    if (state.cullFace != Face::Front) state.polygonBack = state.polygonFront;
    return state;
}

std::unique_ptr<BatchChunk> makeChunk() { return std::make_unique<BatchChunk>(kChunkVertices, kChunkBatches); }

}  // namespace

Pipeline::Pipeline(Framebuffer& framebuffer)
    : chunk_(makeChunk()),
      batch_(std::make_unique<BatchEntry>()),
      vertices_(&chunk_->vertices),
      lightings_(std::make_unique<LightingPool>()),
      drawer_(std::make_unique<BatchDrawer>(framebuffer)) {
    if (workerThreadCount() > 1) {
        std::vector<std::unique_ptr<BatchChunk>> spare(kChunks - 1);
        for (auto& chunk : spare) chunk = makeChunk();
        thread_ = std::make_unique<BatchThread>(*drawer_, framebuffer, std::move(spare));
    }
}

Pipeline::~Pipeline() = default;

std::size_t Pipeline::batchSize() const { return openFirst_ - batch_->first; }

StateRef Pipeline::intern(const DrawState& state) { return states_.intern(withCulledFaceModes(state)); }

void Pipeline::beginPrimitive(const StateRef& state, PrimitiveMode mode, QuadSplit quadSplit) {
    BatchEntry& batch = *batch_;
    buffer_.beginPrimitive();
    const bool edgeFlags = buffer_.has(VertexAttribute::EdgeFlag);
    if (batchSize() > 0 &&
        (mode != batch.mode || quadSplit != batch.quadSplit || !isMergeable(mode) ||
         (state != batch.state && !(*state == *batch.state)) || edgeFlags != batch.edgeFlagsPerVertex)) {
        closeBatch();
    }
    batch.edgeFlagsPerVertex = edgeFlags;
    batch.colorInFormat = buffer_.has(VertexAttribute::Color);
    batch.state = state;
    batch.methods = methods_;
    batch.mode = mode;
    batch.quadSplit = quadSplit;
    cuttable_ = canCut(batch);
    insidePrimitive_ = true;
    loopContinued_ = false;
    litByCaller_ = false;
    MYGL_INVARIANT(openCount() == 0);
}

void Pipeline::closeBatchInPrimitive() {
    // A full buffer keeps the reference's vertex format.
    const bool colors = batch_->colorsPerVertex, colorInFormat = batch_->colorInFormat;
    closeBatch();
    batch_->colorsPerVertex = colorsPerVertex_ = colors, batch_->colorInFormat = colorInFormat;
}

void Pipeline::handOverPart() {
    keepOpenVertices(openCount());
    closeBatchInPrimitive();
}

std::size_t Pipeline::wrapOpenPrimitive() {
    const PrimitiveMode mode = batch_->mode;
    const std::size_t count = openCount();
    const WrapSplit split = splitAtWrap(mode, count, loopContinued_);
    std::array<Vertex, std::tuple_size_v<decltype(split.carried)>> carried;
    std::array<LightingOutputs, carried.size()> carriedOutputs;
    MYGL_INVARIANT(split.carriedCount <= carried.size());
    const std::size_t carriedCount = std::min(split.carriedCount, carried.size());  // (a bound the compiler sees)
    for (std::size_t i = 0; i < carriedCount; ++i) carried[i] = (*vertices_)[openFirst_ + split.carried[i]];
    if (litByCaller_) {
        syncOutputs();
        AppendArray<LightingOutputs>& outputs = chunk_->lightingOutputs;
        for (std::size_t i = 0; i < carriedCount; ++i) carriedOutputs[i] = outputs[openFirst_ + split.carried[i]];
        outputs.erase(openFirst_, split.drawnFirst);
    }
    // The part drawn: drawnCount vertices from drawnFirst.
    vertices_->erase(openFirst_, split.drawnFirst);
    vertices_->truncate(openFirst_ + split.drawnCount);
    if (mode == PrimitiveMode::LineLoop) batch_->mode = PrimitiveMode::LineStrip;
    keepOpenVertices(usableVertexCount(batch_->mode, openCount()));
    vertices_->truncate(openFirst_);
    if (litByCaller_) syncOutputs();
    closeBatchInPrimitive();
    batch_->mode = mode;
    // (A part that carries all its vertices over starts the primitive again as it was.)
    if (mode == PrimitiveMode::LineLoop && split.carriedCount < count) loopContinued_ = true;
    vertices_->append(carried.data(), carried.data() + carriedCount);
    if (litByCaller_) {
        syncOutputs();
        std::copy_n(carriedOutputs.begin(), carriedCount, chunk_->lightingOutputs.end() - carriedCount);
    }
    return carriedCount;
}

void Pipeline::wrapBuffer() { buffer_.wrap(wrapOpenPrimitive()); }

void Pipeline::widen(VertexAttribute attribute, int size) {
    std::size_t carried = 0;
    if (insidePrimitive_) {
        if (buffer_.full()) wrapBuffer();
        if (buffer_.hasVertices()) carried = wrapOpenPrimitive();
    } else if (buffer_.hasVertices()) {
        closeBatch();
    }
    buffer_.widen(attribute, size, insidePrimitive_, carried);
    if (attribute == VertexAttribute::EdgeFlag) batch_->edgeFlagsPerVertex = true;
}

void Pipeline::startColorsPerVertex() {
    // The open quads' whole quads so far belong to the draw without colors (the reference
    // carries only an incomplete quad over).
    if (batch_->mode == PrimitiveMode::Quads) keepOpenVertices(openCount() - openCount() % 4);
    closeBatch();
    batch_->colorsPerVertex = colorsPerVertex_ = true;
}

void Pipeline::endPrimitive() {
    if (buffer_.full()) wrapBuffer();
    const std::size_t inBuffer = openCount();
    // A GL_LINE_LOOP that wrapped ends as a line strip back to its first vertex.
    const bool loopClosed = batch_->mode == PrimitiveMode::LineLoop && loopContinued_;
    if (loopClosed) {
        if (litByCaller_) {
            syncOutputs();
            chunk_->lightingOutputs.push_back(chunk_->lightingOutputs[openFirst_]);
            chunk_->lightingOutputs.erase(openFirst_, 1);
        }
        vertices_->push_back((*vertices_)[openFirst_]);
        vertices_->erase(openFirst_, 1);
        batch_->mode = PrimitiveMode::LineStrip;
    }
    const BatchEntry& batch = *batch_;
    const std::size_t count = openCount();
    ++submitted_.primitivesByMode[static_cast<std::size_t>(loopClosed ? PrimitiveMode::LineLoop : batch.mode)];
    const std::size_t usable = usableVertexCount(batch.mode, count);
    keepOpenVertices(usable);
    vertices_->truncate(openFirst_);
    if (litByCaller_) syncOutputs();
    litByCaller_ = false;
    cuttable_ = false;
    insidePrimitive_ = false;
    // The reference keeps an incomplete tail's vertices in its buffer, so the next block is not
    // contiguous and is not merged: dropping vertices ends the batch (measured with OSMesa).
    const bool droppedVertices = usable < count;
    if (buffer_.endPrimitive(batch.mode, inBuffer, loopClosed)) {
        closeBatch();
        buffer_.flush();
    } else if (!isMergeable(batch.mode) || droppedVertices || (canCut(batch) && batchSize() >= kPartVertices)) {
        closeBatch();
    }
}

bool Pipeline::acceptsIndexedParts(const DrawState& state, PrimitiveMode mode) {
    return mode == PrimitiveMode::Triangles && !state.selection && !state.feedback &&
           state.polygonFront == PolygonMode::Fill && state.polygonBack == PolygonMode::Fill;
}

Pipeline::IndexedPart Pipeline::addIndexedPart(std::size_t vertexCount, std::size_t indexCount) {
    closeBatchInPrimitive();  // the part before, or the primitive's vertices so far
    MYGL_INVARIANT(openCount() == 0);
    BatchChunk& chunk = *chunk_;
    const std::size_t firstVertex = chunk.vertices.size(), firstIndex = chunk.indices.size();
    chunk.vertices.appendUninitialized(vertexCount);  // the caller fills them whole
    chunk.indices.appendUninitialized(indexCount);
    openFirst_ = chunk.vertices.size();  // the batch's
    batch_->indexCount = indexCount;
    submitted_.vertices += indexCount;
    return {std::span(chunk.vertices).subspan(firstVertex), std::span(chunk.indices).subspan(firstIndex)};
}

void Pipeline::submit(const StateRef& state, PrimitiveMode mode, std::span<const Vertex> vertices) {
    beginPrimitive(state, mode, QuadSplit::ByPath);
    colorPerVertex();  // vertices given whole carry their own colors and edge flags
    batch_->edgeFlagsPerVertex = true;
    for (const Vertex& vertex : vertices) addVertex() = vertex;
    endPrimitive();
}

void Pipeline::setTransform(const VertexTransform& transform) {
    if (transform == batch_->transform) return;
    closeBatch();  // (keeps the header: the batches after it take the new matrices)
    batch_->transform = transform;
}

void Pipeline::setLighting(const VertexLighting& lighting) {
    if (lightings_->full()) drawSubmitted();
    closeBatch();
    batch_->lighting = lightings_->keep(lighting);
}

void Pipeline::setUnlit() {
    if (!batch_->lighting) return;
    closeBatch();
    batch_->lighting = nullptr;
}

void Pipeline::lightOpenBatch() {
    litByCaller_ = true;
    syncOutputs();
    if (!batch_->lighting) return;
    const std::size_t first = batch_->first, count = vertices_->size() - first;
    // (With the open primitive's so far.)
    batch_->lighting->lightVertices(std::span(chunk_->vertices).subspan(first), chunk_->outputsOf(first, count),
                                    batch_->state->twoSidedColors);
    batch_->lighting = nullptr;
}

LightingOutputs& Pipeline::outputsOfLastVertex() {
    syncOutputs();
    return chunk_->lightingOutputs[chunk_->lightingOutputs.size() - 1];
}

void Pipeline::syncOutputs() { chunk_->resizeOutputs(vertices_->size()); }

void Pipeline::endBatch() {
    buffer_.flushAndReset();
    closeBatch();
}

void Pipeline::closeBatch() {
    if (batchSize() == 0) return;
    batch_->count = batchSize();
    BatchEntry& closed = chunk_->batches.emplace_back(*batch_);
    // Outputs a batch needs but nothing lights are zeros (as glMaterial's vertices' successors in it).
    AppendArray<LightingOutputs>& outputs = chunk_->lightingOutputs;
    if (!closed.lighting && needsLightingOutputs(*closed.state) && outputs.size() < closed.first + closed.count) {
        const std::size_t missing = closed.first + closed.count - outputs.size();
        std::fill_n(outputs.appendUninitialized(missing), missing, LightingOutputs{});
    }
    // Without a color per vertex the color is a constant of the draw, not an interpolation of
    // equal values (which perspective would blur by one unit here and there): flat. Under
    // texturing only when the reference's vertex format has no colour either (Mesa's vertex
    // program then reads the current colour as a uniform, which the fragment shader takes exactly).
    const bool textured = closed.state->texture.env != TextureEnv::Off;
    if (!closed.colorsPerVertex && !(textured && closed.colorInFormat)) closed.state = flatVersion(closed.state);
    batch_->first = openFirst_;
    batch_->firstIndex = chunk_->indices.size();
    batch_->indexCount = 0;
    batch_->colorsPerVertex = colorsPerVertex_ = false;
    if (openFirst_ >= kPartVertices || chunk_->indices.size() >= kPartVertices) handOverChunk();
}

StateRef Pipeline::flatVersion(const StateRef& state) {
    if (state->shadeModel == ShadeModel::Flat) return state;
    if (lastFlatVersion_.first != state) {
        DrawState flat = *state;
        flat.shadeModel = ShadeModel::Flat;
        lastFlatVersion_ = {state, states_.intern(flat)};
    }
    return lastFlatVersion_.second;
}

void Pipeline::handOverChunk() {
    if (chunk_->batches.empty()) return;
    const DenormalsAreZero denormals;
    const bool moving = openCount() > 0;  // (rare: glColor after a glBegin's first vertices)
    if (moving) moved_.assign(vertices_->begin() + openFirst_, vertices_->end());
    if (moving && litByCaller_) {
        syncOutputs();
        movedOutputs_.assign(chunk_->lightingOutputs.begin() + openFirst_, chunk_->lightingOutputs.end());
    }
    vertices_->truncate(openFirst_);
    if (thread_) {
        chunk_ = thread_->post(std::move(chunk_));
    } else {
        drawer_->draw(*chunk_);
        chunk_->clear();
    }
    vertices_ = &chunk_->vertices;
    if (moving) vertices_->append(moved_.begin(), moved_.end());
    if (moving && litByCaller_) chunk_->lightingOutputs.append(movedOutputs_.begin(), movedOutputs_.end());
    openFirst_ = 0;
    batch_->first = 0;
    batch_->firstIndex = 0;
}

void Pipeline::drawSubmitted() {
    const DenormalsAreZero denormals;
    closeBatch();
    handOverChunk();
    if (thread_) thread_->wait();
    drawer_->flushTriangles();
    // Nothing is queued now: the triangles' slots are free for what comes next.
    if (thread_) thread_->releaseTriangles();
    drawer_->releaseTriangles();
    // Nothing points to the lightings now but the open batch's header, which keeps its own.
    const VertexLighting* open = batch_->lighting;
    lightings_->release();
    if (open) batch_->lighting = lightings_->keep(*open);
}

void Pipeline::finish() {
    buffer_.flushAndReset();
    drawSubmitted();
    const DenormalsAreZero denormals;
    drawer_->flush();
}

HitRange Pipeline::takeHits() {
    buffer_.flushAndReset();
    drawSubmitted();
    return drawer_->takeHits();
}

FeedbackPrimitives Pipeline::takeFeedback() {
    buffer_.flushAndReset();
    drawSubmitted();
    return drawer_->takeFeedback();
}

Stats Pipeline::stats() const { return submitted_ + drawer_->stats(); }

void Pipeline::resetStats() {
    drawSubmitted();
    submitted_ = {};
    drawer_->resetStats();
}

}  // namespace glrenderer
