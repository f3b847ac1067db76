#pragma once
// The current vertex attributes and glVertex: what glBegin/glEnd blocks and vertex arrays
// (glArrayElement, glDrawArrays, glDrawElements) both feed vertices through.
#include <xmmintrin.h>

#include <array>
#include <cstddef>
#include <type_traits>

#include "clamp_to_unit.h"
#include "context_state.h"

namespace mygl {

// glBegin; `quadSplit` V1V3 for the draws whose quads the reference converts to triangles first.
void begin(GLenum mode, glrenderer::QuadSplit quadSplit);

// Quads drawn from a display list reach the reference's rasterizer already as triangles.
inline glrenderer::QuadSplit quadSplitOf(const Context::State& s, bool indexed = false) {
    return indexed || s.lists.replaying() ? glrenderer::QuadSplit::V1V3 : glrenderer::QuadSplit::ByPath;
}
void end();

// Lighting as glBegin prepares it: the pipeline's vertex stage lights the primitive's vertices
// with the state of that moment (lighting.cpp).
void prepareLighting(Context::State& s);
// A vertex lit on the program's thread with the current state (after glMaterial inside
// glBegin/glEnd): its colour, and into `outputs` (unless null) its back and secondary colours.
void lightVertex(Context::State& s, glrenderer::Vertex& v, glrenderer::LightingOutputs* outputs);

// Inlined into each glVertex, the position (x, y, z, w) in a register from the call's arguments
// to the vertex's store: a glm::vec4 built there went to the stack in two halves and was loaded
// whole, a store-forwarding stall that was 40% of glVertex3f's time in the torus.
// The vertex goes to the pipeline as given; its vertex stage transforms it. `size`: glVertex2, 3 or 4.
// `pushVertex`: the vertex with the current attributes, once the vertex format has its position.
[[gnu::always_inline]] inline void pushVertex(Context::State& s, __m128 object) {
    // Written whole: the pipeline's new vertex is not initialized.
    glrenderer::Vertex& v = s.pipeline.addVertex();
    // Lit colours come from the current colour unclamped: lit by the pipeline's vertex stage, or
    // here after glMaterial inside glBegin/glEnd. Unlit, a colour the vertex format does not hold
    // is the reference's constant (a NaN component 0).
    const glm::vec4 color = s.lightingEnabled            ? s.color
                            : s.pipeline.colorInFormat() ? s.vertexColor
                                                         : glrenderer::saturateConstant(s.color);
    glrenderer::writeVertex(v, object, color, s.normal, s.texCoord, s.edgeFlag, s.pipeline.streamsVertices());
    if (s.lightingEnabled && s.lightingOnProgramThread) lightVertex(s, v, &s.pipeline.outputsOfLastVertex());
}
// The same for a position that is a glm::vec4 already (vertex arrays, evaluators, glRect).
inline void pushVertex(Context::State& s, const glm::vec4& object) { pushVertex(s, _mm_loadu_ps(&object.x)); }
[[gnu::always_inline]] inline void addVertex(__m128 object, int size) {
    Context::State* s = currentState();
    if (!s || !s->insideBeginEnd) return;  // outside glBegin/glEnd a vertex is undefined: ignored
    s->pipeline.attribute(glrenderer::VertexAttribute::Position, size);
    pushVertex(*s, object);
}
inline void addVertex(const glm::vec4& object, int size) { addVertex(_mm_loadu_ps(&object.x), size); }

template <class T>
[[gnu::always_inline]] inline void vertexv(const T* v, int n) {  // as addVertex
    if (!v) return;
    addVertex(_mm_setr_ps(static_cast<float>(v[0]), static_cast<float>(v[1]), n > 2 ? static_cast<float>(v[2]) : 0.0f,
                          n > 3 ? static_cast<float>(v[3]) : 1.0f),
              n);
}

// GL clamps a vertex's colour to [0, 1] before it is interpolated (the reference's vertex stage
// saturates it); the current colour itself stays as given, as glGet reports it.
// `size`: as the reference stores it (see glrenderer::VertexAttribute).
// The colour comes in a register: built as a glm::vec4 on the stack in parts and loaded whole, it
// stalled on store forwarding (three quarters of glColor3f's time in the torus).
[[gnu::always_inline]] inline void setColor(__m128 c, int size) {  // as addVertex
    Context::State* s = currentState();
    if (!s) return;
    s->pipeline.attribute(glrenderer::VertexAttribute::Color, size);
    _mm_storeu_ps(&s->color.x, c);
    _mm_storeu_ps(&s->vertexColor.x, saturate(c));
    if (s->insideBeginEnd) s->pipeline.colorPerVertex();
}

// Integer colour and normal components to float as the GL spec (and the reference) converts
// them: unsigned c to c / (2^b - 1), signed c to (2c + 1) / (2^b - 1).
// (Bytes from a table of those quotients, computed when compiled: a division per component was
// most of the cost of a mesh's byte colours in glDrawElements.)
inline constexpr std::array<float, 256> kUnitOfByte = [] {
    std::array<float, 256> quotients{};
    for (std::size_t v = 0; v < quotients.size(); ++v) quotients[v] = static_cast<float>(v) / 255.0f;
    return quotients;
}();
inline float toFloat(GLubyte v) { return kUnitOfByte[v]; }
inline float toFloat(GLushort v) { return static_cast<float>(v) * (1.0f / 65535.0f); }
inline float toFloat(GLuint v) { return static_cast<float>(static_cast<double>(v) * (1.0 / 4294967295.0)); }
inline float toFloat(GLbyte v) { return (2.0f * static_cast<float>(v) + 1.0f) * (1.0f / 255.0f); }
inline float toFloat(GLshort v) { return (2.0f * static_cast<float>(v) + 1.0f) * (1.0f / 65535.0f); }
// In float, then scaled in double, as the reference's INT_TO_FLOAT (not the exact (2c + 1) / (2^32 - 1)).
inline float toFloat(GLint v) {
    return static_cast<float>((2.0f * static_cast<float>(v) + 1.0f) * (1.0 / 4294967294.0));
}
inline float toFloat(GLfloat v) { return v; }
inline float toFloat(GLdouble v) { return static_cast<float>(v); }

template <class T>
[[gnu::always_inline]] inline void colorv(const T* v, int n) {  // as addVertex
    // The reference passes glColor3 of any type but float on as glColor4f(r, g, b, 1).
    const int size = n == 3 && std::is_same_v<T, GLfloat> ? 3 : 4;
    if (v) setColor(_mm_setr_ps(toFloat(v[0]), toFloat(v[1]), toFloat(v[2]), n > 3 ? toFloat(v[3]) : 1.0f), size);
}

template <class T>
inline void normalv(const T* v) {
    Context::State* s = currentState();
    if (!s || !v) return;
    s->pipeline.attribute(glrenderer::VertexAttribute::Normal, 3);
    s->normal = {toFloat(v[0]), toFloat(v[1]), toFloat(v[2])};
}

template <class T>
inline void texCoordv(const T* v, int n) {
    Context::State* s = currentState();
    if (!s || !v) return;
    s->pipeline.attribute(glrenderer::VertexAttribute::TexCoord, n);
    s->texCoord = {static_cast<float>(v[0]), n > 1 ? static_cast<float>(v[1]) : 0.0f,
                   n > 2 ? static_cast<float>(v[2]) : 0.0f, n > 3 ? static_cast<float>(v[3]) : 1.0f};
}

inline void setEdgeFlag(bool flag) {
    Context::State* s = currentState();
    if (!s) return;
    s->pipeline.attribute(glrenderer::VertexAttribute::EdgeFlag, 1);
    s->edgeFlag = flag;
}

}  // namespace mygl
