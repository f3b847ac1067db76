// Vertex arrays: the gl*Pointer calls, glEnableClientState, glArrayElement, glDrawArrays,
// glDrawElements, glInterleavedArrays and glGetPointerv. An element is fed through the same
// calls as glColor/glNormal/glTexCoord/glEdgeFlag/glVertex; a draw is one glBegin/glEnd of its
// own, as the reference draws it, leaving the current attributes as they were.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include "client_arrays.h"
#include "compiled.h"
#include "vertex_input.h"

namespace mygl {
namespace {

// The immediate-mode call an array's components stand for, taking them as T.
template <class T>
struct TexCoordCall {
    static void call(const T* v, int n) { texCoordv(v, n); }
};
template <class T>
struct ColorCall {
    static void call(const T* v, int n) { colorv(v, n); }
};
template <class T>
struct NormalCall {
    static void call(const T* v, int) { normalv(v); }
};
template <class T>
struct VertexCall {
    static void call(const T* v, int n) { vertexv(v, n); }
};
template <class T>
struct EdgeFlagCall {
    static void call(const T* v, int) { setEdgeFlag(v[0] != 0); }
};

// The `n` components at `p` (any alignment) read as T and handed to Call.
template <class T, template <class> class Call>
void readComponents(const void* p, int n) {
    T values[4]{};
    for (int k = 0; k < n; ++k)
        std::memcpy(&values[k], static_cast<const unsigned char*>(p) + k * sizeof(T), sizeof(T));
    Call<T>::call(values, n);
}

// An enabled array as a draw reads it: where its elements start, their step, and the call its
// components go through, chosen by type once per draw rather than per element.
class ArrayReader {
public:
    ArrayReader() = default;
    template <template <class> class Call>
    static ArrayReader of(const ClientArray& a) {
        ArrayReader r;
        r.base_ = static_cast<const unsigned char*>(a.pointer);
        r.step_ =
            a.stride ? static_cast<std::size_t>(a.stride) : static_cast<std::size_t>(a.size) * componentBytes(a.type);
        r.size_ = a.size;
        switch (a.type) {
        case GL_BYTE: r.read_ = &readComponents<GLbyte, Call>; break;
        case GL_UNSIGNED_BYTE: r.read_ = &readComponents<GLubyte, Call>; break;
        case GL_SHORT: r.read_ = &readComponents<GLshort, Call>; break;
        case GL_UNSIGNED_SHORT: r.read_ = &readComponents<GLushort, Call>; break;
        case GL_INT: r.read_ = &readComponents<GLint, Call>; break;
        case GL_UNSIGNED_INT: r.read_ = &readComponents<GLuint, Call>; break;
        case GL_FLOAT: r.read_ = &readComponents<GLfloat, Call>; break;
        case GL_DOUBLE: r.read_ = &readComponents<GLdouble, Call>; break;
        default: r.read_ = nullptr;
        }
        return r;
    }
    void operator()(std::size_t i) const {
        if (read_) read_(base_ + i * step_, size_);
    }

private:
    const unsigned char* base_ = nullptr;
    std::size_t step_ = 0;
    int size_ = 0;
    void (*read_)(const void*, int) = nullptr;
};

// The enabled arrays' readers in GL's order for an element, the vertex last.
class ElementReader {
public:
    explicit ElementReader(const ClientArrays& arrays) {
        if (arrays.edgeFlag.enabled) readers_[count_++] = ArrayReader::of<EdgeFlagCall>(arrays.edgeFlag);
        if (arrays.texCoord.enabled) readers_[count_++] = ArrayReader::of<TexCoordCall>(arrays.texCoord);
        if (arrays.color.enabled) readers_[count_++] = ArrayReader::of<ColorCall>(arrays.color);
        if (arrays.normal.enabled) readers_[count_++] = ArrayReader::of<NormalCall>(arrays.normal);
        if (arrays.vertex.enabled) readers_[count_++] = ArrayReader::of<VertexCall>(arrays.vertex);
    }
    // glArrayElement(i).
    void operator()(std::size_t i) const {
        for (int k = 0; k < count_; ++k) readers_[static_cast<std::size_t>(k)](i);
    }

private:
    std::array<ArrayReader, 5> readers_;
    int count_ = 0;
};

void emitElement(const ClientArrays& arrays, std::size_t i) { ElementReader{arrays}(i); }

// The arrays of a typical mesh (positions in float; colours in float or unsigned bytes; normals
// and texture coordinates in float; no edge flags) read straight into the current attributes and
// the pipeline's vertices. Once a draw's first element has set the vertex format through the
// usual calls, each other element stores what those calls would store, without their lookups.
class MeshArrays {
public:
    static std::optional<MeshArrays> of(const ClientArrays& a) {
        const auto is = [](const ClientArray& array, GLenum type) { return !array.enabled || array.type == type; };
        if (!a.vertex.enabled || a.vertex.type != GL_FLOAT || a.edgeFlag.enabled || !is(a.normal, GL_FLOAT) ||
            !is(a.texCoord, GL_FLOAT) || !(is(a.color, GL_FLOAT) || is(a.color, GL_UNSIGNED_BYTE))) {
            return std::nullopt;
        }
        return MeshArrays(a);
    }

    void emit(Context::State& s, std::size_t i) const {
        if (texCoord_.size) s.texCoord = texCoord_.read(i, {0.0f, 0.0f, 0.0f, 1.0f});
        if (color_.size) {
            const glm::vec4 c = colorBytes_ ? colorFromBytes(i) : color_.read(i, {0.0f, 0.0f, 0.0f, 1.0f});
            s.color = c;
            s.vertexColor = saturate(c);
        }
        if (normal_.size) s.normal = glm::vec3(normal_.read(i, {}));
        pushVertex(s, vertex_.read(i, {0.0f, 0.0f, 0.0f, 1.0f}));
    }

    // The vertex emit() would push for element i, the current attributes left as they are.
    void fill(const Context::State& s, std::size_t i, glrenderer::Vertex& out) const {
        const glm::vec4 texCoord = texCoord_.size ? texCoord_.read(i, {0.0f, 0.0f, 0.0f, 1.0f}) : s.texCoord;
        const glm::vec3 normal = normal_.size ? glm::vec3(normal_.read(i, {})) : s.normal;
        glm::vec4 color = s.lightingEnabled ? s.color : s.vertexColor;
        if (color_.size) {
            const glm::vec4 c = colorBytes_ ? colorFromBytes(i) : color_.read(i, {0.0f, 0.0f, 0.0f, 1.0f});
            color = s.lightingEnabled ? c : saturate(c);  // lit unclamped by the pipeline (pushVertex)
        }
        const glm::vec4 position = vertex_.read(i, {0.0f, 0.0f, 0.0f, 1.0f});
        glrenderer::writeVertex(out, _mm_loadu_ps(&position.x), color, normal, texCoord, s.edgeFlag,
                                s.pipeline.streamsVertices());
    }
    bool hasColors() const { return color_.size > 0; }

private:
    struct Source {
        const unsigned char* base = nullptr;
        std::size_t step = 0;
        int size = 0;  // 0: not enabled
        // Element i's components, the missing ones taken from `rest` (copies of a size known
        // when compiled: one of a size known only at run time is a library call).
        glm::vec4 read(std::size_t i, glm::vec4 rest) const {
            const unsigned char* element = base + i * step;
            float v[4];
            switch (size) {
            case 4: std::memcpy(v, element, 4 * sizeof(float)); return {v[0], v[1], v[2], v[3]};
            case 3: std::memcpy(v, element, 3 * sizeof(float)); return {v[0], v[1], v[2], rest.w};
            case 2: std::memcpy(v, element, 2 * sizeof(float)); return {v[0], v[1], rest.z, rest.w};
            default: std::memcpy(v, element, sizeof(float)); return {v[0], rest.y, rest.z, rest.w};
            }
        }
    };
    static Source sourceOf(const ClientArray& a) {
        if (!a.enabled) return {};
        const std::size_t step =
            a.stride ? static_cast<std::size_t>(a.stride) : static_cast<std::size_t>(a.size) * componentBytes(a.type);
        return {static_cast<const unsigned char*>(a.pointer), step, a.size};
    }
    explicit MeshArrays(const ClientArrays& a)
        : vertex_(sourceOf(a.vertex)),
          color_(sourceOf(a.color)),
          normal_(sourceOf(a.normal)),
          texCoord_(sourceOf(a.texCoord)),
          colorBytes_(a.color.type == GL_UNSIGNED_BYTE) {}

    glm::vec4 colorFromBytes(std::size_t i) const {
        const unsigned char* b = color_.base + i * color_.step;
        return {toFloat(b[0]), toFloat(b[1]), toFloat(b[2]), color_.size > 3 ? toFloat(b[3]) : 1.0f};
    }

    Source vertex_, color_, normal_, texCoord_;
    bool colorBytes_;
};

std::size_t readIndex(GLenum type, const void* indices, std::size_t k) {
    const auto* bytes = static_cast<const unsigned char*>(indices);
    if (type == GL_UNSIGNED_BYTE) return bytes[k];
    if (type == GL_UNSIGNED_SHORT) {
        GLushort index;
        std::memcpy(&index, bytes + 2 * k, 2);
        return index;
    }
    GLuint index;
    std::memcpy(&index, bytes + 4 * k, 4);
    return index;
}

// The elements a draw reads, in order: `count` from `first` (glDrawArrays), or the `count`
// indices of `type` at `indices` (glDrawElements).
struct Elements {
    std::size_t first = 0, count = 0;
    const void* indices = nullptr;
    GLenum type = 0;
    std::size_t operator[](std::size_t k) const { return indices ? readIndex(type, indices, k) : first + k; }
};

// Index k at `indices`, of type Index (read at any alignment).
template <class Index>
std::uint32_t indexAt(const void* indices, std::size_t k) {
    Index index;
    std::memcpy(&index, static_cast<const unsigned char*>(indices) + k * sizeof(Index), sizeof(Index));
    return index;
}

// glDrawElements' independent triangles from a typical mesh's arrays, drawn in the pipeline's
// indexed parts: each part's elements between its smallest and largest index are read once
// (most are shared by several triangles), and its indices point into them. A part whose indices
// spread wider than their number takes a vertex per index instead.
template <class Index>
void drawIndexedParts(Context::State& s, const MeshArrays& mesh, const void* indices, std::size_t count) {
    constexpr std::size_t kPart = glrenderer::Pipeline::kPartVertices;
    count -= count % 3;  // glEnd drops an incomplete triangle
    for (std::size_t first = 0; first < count; first += kPart) {
        const std::size_t n = std::min(kPart, count - first);
        std::uint32_t low = indexAt<Index>(indices, first), high = low;
        for (std::size_t k = first + 1; k < first + n; ++k) {
            const std::uint32_t index = indexAt<Index>(indices, k);
            low = std::min(low, index), high = std::max(high, index);
        }
        const bool compact = high - low < n;
        const glrenderer::Pipeline::IndexedPart part = s.pipeline.addIndexedPart(compact ? high - low + 1 : n, n);
        if (compact) {
            for (std::size_t j = 0; j < part.vertices.size(); ++j) mesh.fill(s, low + j, part.vertices[j]);
            for (std::size_t k = 0; k < n; ++k) part.indices[k] = indexAt<Index>(indices, first + k) - low;
        } else {
            for (std::size_t k = 0; k < n; ++k) {
                mesh.fill(s, indexAt<Index>(indices, first + k), part.vertices[k]);
                part.indices[k] = static_cast<std::uint32_t>(k);
            }
        }
    }
}

void drawIndexedParts(Context::State& s, const MeshArrays& mesh, const Elements& elements) {
    if (mesh.hasColors()) s.pipeline.colorPerVertex();  // as glColor inside glBegin/glEnd
    switch (elements.type) {
    case GL_UNSIGNED_BYTE: return drawIndexedParts<GLubyte>(s, mesh, elements.indices, elements.count);
    case GL_UNSIGNED_SHORT: return drawIndexedParts<GLushort>(s, mesh, elements.indices, elements.count);
    default: return drawIndexedParts<GLuint>(s, mesh, elements.indices, elements.count);
    }
}

// The elements a draw reads, copied, with arrays that point into the copy: what a display list
// keeps of glArrayElement, glDrawArrays and glDrawElements (GL reads the arrays when the command
// is compiled, not when the list runs).
struct ArraySnapshot {
    ClientArrays arrays;
    std::vector<unsigned char> bytes;
};

std::shared_ptr<const ArraySnapshot> snapshot(const ClientArrays& source, const Elements& elements) {
    auto copy = std::make_shared<ArraySnapshot>();
    copy->arrays = source;
    ClientArray* all[] = {&copy->arrays.vertex, &copy->arrays.normal,   &copy->arrays.color,
                          &copy->arrays.index,  &copy->arrays.texCoord, &copy->arrays.edgeFlag};
    std::vector<std::size_t> offsets;
    for (ClientArray* a : all) {
        offsets.push_back(copy->bytes.size());
        if (!a->enabled) continue;
        const std::size_t elementBytes = static_cast<std::size_t>(a->size) * componentBytes(a->type);
        for (std::size_t k = 0; k < elements.count; ++k) {
            const auto* from = static_cast<const unsigned char*>(a->element(elements[k]));
            copy->bytes.insert(copy->bytes.end(), from, from + elementBytes);
        }
        a->stride = 0;
    }
    for (std::size_t k = 0; k < std::size(all); ++k) all[k]->pointer = copy->bytes.data() + offsets[k];
    return copy;
}

// Draws `elements` of `arrays` as one primitive of `mode`, a draw of its own. The reference
// converts indexed quads to triangles before it draws them.
void drawElementsOf(Context::State& s, GLenum mode, const ClientArrays& arrays, const Elements& elements,
                    bool indexed) {
    if (!arrays.vertex.enabled) return;  // no positions: nothing is drawn
    const glm::vec4 color = s.color, vertexColor = s.vertexColor, texCoord = s.texCoord;
    const glm::vec3 normal = s.normal;
    const bool edgeFlag = s.edgeFlag;
    endBatch(s);
    s.pipeline.drawFromArrays(true);
    begin(mode, quadSplitOf(s, indexed));
    const ElementReader element(arrays);
    const std::optional<MeshArrays> mesh = MeshArrays::of(arrays);
    if (mesh && elements.indices && !s.lightingOnProgramThread &&
        glrenderer::Pipeline::acceptsIndexedParts(*s.draw, static_cast<glrenderer::PrimitiveMode>(mode))) {
        drawIndexedParts(s, *mesh, elements);
    } else {
        for (std::size_t k = 0; k < elements.count; ++k) {
            if (k > 0 && mesh)
                mesh->emit(s, elements[k]);
            else
                element(elements[k]);
        }
    }
    end();
    endBatch(s);
    s.pipeline.drawFromArrays(false);
    s.color = color, s.vertexColor = vertexColor, s.texCoord = texCoord, s.normal = normal, s.edgeFlag = edgeFlag;
}

// Runs a draw now, or keeps it in the list being compiled (and runs it too in
// GL_COMPILE_AND_EXECUTE).
void drawOrCompile(Context::State& s, GLenum mode, const Elements& elements, bool indexed) {
    if (s.lists.compiling()) {
        s.lists.add([mode, kept = snapshot(s.arrays, elements), count = elements.count, indexed] {
            if (Context::State* now = stateOutsideBeginEnd())
                drawElementsOf(*now, mode, kept->arrays, {0, count}, indexed);
        });
        if (!s.lists.executingWhileCompiling()) return;
    }
    drawElementsOf(s, mode, s.arrays, elements, indexed);
}

// The error of a draw with bad arguments; compiled into a list, it is the list's when it runs,
// as for every compiled command.
void drawError(Context::State& s, GLenum error) {
    if (s.lists.compiling()) {
        s.lists.add([error] {
            if (Context::State* now = stateOutsideBeginEnd()) setError(*now, error);
        });
        if (!s.lists.executingWhileCompiling()) return;
    }
    setError(s, error);
}

void drawArrays(GLenum mode, GLint first, GLsizei count) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode > GL_POLYGON) return drawError(*s, GL_INVALID_ENUM);
    if (first < 0 || count < 0) return drawError(*s, GL_INVALID_VALUE);
    drawOrCompile(*s, mode, {static_cast<std::size_t>(first), static_cast<std::size_t>(count)}, false);
}

void drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode > GL_POLYGON) return drawError(*s, GL_INVALID_ENUM);
    if (count < 0) return drawError(*s, GL_INVALID_VALUE);
    if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
        return drawError(*s, GL_INVALID_ENUM);
    if (!indices) return;
    drawOrCompile(*s, mode, {0, static_cast<std::size_t>(count), indices, type}, true);
}

// glArrayElement may be called inside glBegin/glEnd (that is what it is for).
void arrayElement(GLint i) {
    Context::State* s = currentState();
    if (!s || i < 0) return;
    const auto element = static_cast<std::size_t>(i);
    if (s->lists.compiling()) {
        s->lists.add([kept = snapshot(s->arrays, {element, 1})] { emitElement(kept->arrays, 0); });
        if (!s->lists.executingWhileCompiling()) return;
    }
    emitElement(s->arrays, element);
}

// Sets an array after the reference's checks: stride, then type, then size.
void setPointer(ClientArray& (*select)(ClientArrays&), GLint size, bool sizeValid, GLenum type, bool typeValid,
                GLsizei stride, const void* pointer) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (stride < 0) return setError(*s, GL_INVALID_VALUE);
    if (!typeValid) return setError(*s, GL_INVALID_ENUM);
    if (!sizeValid) return setError(*s, GL_INVALID_VALUE);
    ClientArray& a = select(s->arrays);
    a.size = size, a.type = type, a.stride = stride, a.pointer = pointer;
}

bool isOneOf(GLenum type, std::initializer_list<GLenum> types) {
    for (GLenum t : types) {
        if (t == type) return true;
    }
    return false;
}

void enableClientState(GLenum name, bool enabled) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    ClientArray* a = s->arrays.find(name);
    if (!a) return setError(*s, GL_INVALID_ENUM);
    a->enabled = enabled;
}

// glInterleavedArrays' formats: which arrays, their sizes, and the colour type.
struct InterleavedFormat {
    GLenum format;
    int texCoords, colors, normals, vertices;
    GLenum colorType;
};
constexpr InterleavedFormat kInterleavedFormats[] = {
    {GL_V2F, 0, 0, 0, 2, 0},
    {GL_V3F, 0, 0, 0, 3, 0},
    {GL_C4UB_V2F, 0, 4, 0, 2, GL_UNSIGNED_BYTE},
    {GL_C4UB_V3F, 0, 4, 0, 3, GL_UNSIGNED_BYTE},
    {GL_C3F_V3F, 0, 3, 0, 3, GL_FLOAT},
    {GL_N3F_V3F, 0, 0, 3, 3, 0},
    {GL_C4F_N3F_V3F, 0, 4, 3, 3, GL_FLOAT},
    {GL_T2F_V3F, 2, 0, 0, 3, 0},
    {GL_T4F_V4F, 4, 0, 0, 4, 0},
    {GL_T2F_C4UB_V3F, 2, 4, 0, 3, GL_UNSIGNED_BYTE},
    {GL_T2F_C3F_V3F, 2, 3, 0, 3, GL_FLOAT},
    {GL_T2F_N3F_V3F, 2, 0, 3, 3, 0},
    {GL_T2F_C4F_N3F_V3F, 2, 4, 3, 3, GL_FLOAT},
    {GL_T4F_C4F_N3F_V4F, 4, 4, 3, 4, GL_FLOAT},
};

void interleavedArrays(GLenum format, GLsizei stride, const void* pointer) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (stride < 0) return setError(*s, GL_INVALID_VALUE);
    const InterleavedFormat* f = nullptr;
    for (const InterleavedFormat& candidate : kInterleavedFormats) {
        if (candidate.format == format) f = &candidate;
    }
    if (!f) return setError(*s, GL_INVALID_ENUM);
    const auto* base = static_cast<const unsigned char*>(pointer);
    const std::size_t colorBytes = f->colorType == GL_UNSIGNED_BYTE ? 4 : 4 * static_cast<std::size_t>(f->colors);
    const std::size_t texBytes = 4 * static_cast<std::size_t>(f->texCoords),
                      normalBytes = 4 * static_cast<std::size_t>(f->normals);
    const std::size_t total =
        texBytes + (f->colors ? colorBytes : 0) + normalBytes + 4 * static_cast<std::size_t>(f->vertices);
    const auto step = stride ? stride : static_cast<GLsizei>(total);
    ClientArrays& a = s->arrays;
    a.edgeFlag.enabled = a.index.enabled = false;
    a.texCoord = {f->texCoords > 0, f->texCoords ? f->texCoords : a.texCoord.size, GL_FLOAT, step, base};
    a.color = {f->colors > 0, f->colors ? f->colors : a.color.size, f->colors ? f->colorType : a.color.type, step,
               base + texBytes};
    const std::size_t normalOffset = texBytes + (f->colors ? colorBytes : 0);
    a.normal = {f->normals > 0, 3, GL_FLOAT, step, base + normalOffset};
    a.vertex = {true, f->vertices, GL_FLOAT, step, base + normalOffset + normalBytes};
    if (!f->texCoords) a.texCoord.pointer = nullptr;
    if (!f->colors) a.color.pointer = nullptr;
    if (!f->normals) a.normal.pointer = nullptr;
}

const void* arrayPointer(const Context::State& s, GLenum name) {
    switch (name) {
    case GL_VERTEX_ARRAY_POINTER: return s.arrays.vertex.pointer;
    case GL_NORMAL_ARRAY_POINTER: return s.arrays.normal.pointer;
    case GL_COLOR_ARRAY_POINTER: return s.arrays.color.pointer;
    case GL_INDEX_ARRAY_POINTER: return s.arrays.index.pointer;
    case GL_TEXTURE_COORD_ARRAY_POINTER: return s.arrays.texCoord.pointer;
    case GL_EDGE_FLAG_ARRAY_POINTER: return s.arrays.edgeFlag.pointer;
    default: return nullptr;
    }
}

ClientArray& vertexArray(ClientArrays& a) { return a.vertex; }
ClientArray& normalArray(ClientArrays& a) { return a.normal; }
ClientArray& colorArray(ClientArrays& a) { return a.color; }
ClientArray& indexArray(ClientArrays& a) { return a.index; }
ClientArray& texCoordArray(ClientArrays& a) { return a.texCoord; }
ClientArray& edgeFlagArray(ClientArrays& a) { return a.edgeFlag; }

const EntryPoint kEntryPoints[] = {
    listed<gl::glVertexPointer,
           +[](GLint size, GLenum type, GLsizei stride, const void* p) {
               setPointer(vertexArray, size, size >= 2 && size <= 4, type,
                          isOneOf(type, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}), stride, p);
           }>(),
    listed<gl::glNormalPointer,
           +[](GLenum type, GLsizei stride, const void* p) {
               setPointer(normalArray, 3, true, type, isOneOf(type, {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}),
                          stride, p);
           }>(),
    listed<gl::glColorPointer,
           +[](GLint size, GLenum type, GLsizei stride, const void* p) {
               setPointer(colorArray, size, size == 3 || size == 4, type,
                          isOneOf(type, {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT,
                                         GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE}),
                          stride, p);
           }>(),
    listed<gl::glIndexPointer,
           +[](GLenum type, GLsizei stride, const void* p) {
               setPointer(indexArray, 1, true, type,
                          isOneOf(type, {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}), stride, p);
           }>(),
    listed<gl::glTexCoordPointer,
           +[](GLint size, GLenum type, GLsizei stride, const void* p) {
               setPointer(texCoordArray, size, size >= 1 && size <= 4, type,
                          isOneOf(type, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE}), stride, p);
           }>(),
    listed<gl::glEdgeFlagPointer,
           +[](GLsizei stride, const void* p) {
               setPointer(edgeFlagArray, 1, true, GL_UNSIGNED_BYTE, true, stride, p);
           }>(),
    listed<gl::glEnableClientState, +[](GLenum name) { enableClientState(name, true); }>(),
    listed<gl::glDisableClientState, +[](GLenum name) { enableClientState(name, false); }>(),
    listed<gl::glInterleavedArrays,
           +[](GLenum format, GLsizei stride, const void* p) { interleavedArrays(format, stride, p); }>(),
    listed<gl::glArrayElement, +[](GLint i) { arrayElement(i); }>(),
    listed<gl::glDrawArrays, +[](GLenum mode, GLint first, GLsizei count) { drawArrays(mode, first, count); }>(),
    listed<gl::glDrawElements, +[](GLenum mode, GLsizei count, GLenum type,
                                   const void* indices) { drawElements(mode, count, type, indices); }>(),
    listed<gl::glGetPointerv,
           +[](GLenum name, void** out) {
               Context::State* s = stateOutsideBeginEnd();
               if (!s || !out) return;
               if (name == GL_SELECTION_BUFFER_POINTER || name == GL_FEEDBACK_BUFFER_POINTER) {
                   *out = name == GL_SELECTION_BUFFER_POINTER ? static_cast<void*>(s->selection.buffer)
                                                              : s->feedback.buffer;
                   return;
               }
               const bool known = name >= GL_VERTEX_ARRAY_POINTER && name <= GL_EDGE_FLAG_ARRAY_POINTER;
               if (!known) return setError(*s, GL_INVALID_ENUM);
               *out = const_cast<void*>(arrayPointer(*s, name));
           }>(),
};

}  // namespace

std::span<const EntryPoint> arrayEntryPoints() { return kEntryPoints; }

}  // namespace mygl
