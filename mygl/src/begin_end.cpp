// glBegin/glEnd and the per-vertex calls: vertices are transformed to clip space as they arrive
// and handed to the pipeline at glEnd.
#include <array>

#include "entry_points.h"

namespace mygl {
namespace {

// Inlined into each glVertex: built in registers there, the position is not stored to the stack
// in parts and read back whole (a store-forwarding stall that was a third of this function).
[[gnu::always_inline]] inline void addVertex(const glm::vec4& object) {
    Context::State* s = currentState();
    if (!s || !s->insideBeginEnd) return;  // outside glBegin/glEnd a vertex is undefined: ignored
    glrenderer::Vertex& v = s->pipeline.addVertex();
    v.position = transform(s->modelviewProjection, object);
    v.color = s->color;
    v.edgeFlag = s->edgeFlag;
    if (s->pipeline.methods().needsEyeSpace()) {  // only the seeds' culling methods look at these
        const Matrix& m = s->modelview.top();
        v.eye = glm::vec3(transform(m, object));
        v.normal = {at(m, 0, 0) * s->normal.x + at(m, 0, 1) * s->normal.y + at(m, 0, 2) * s->normal.z,
                    at(m, 1, 0) * s->normal.x + at(m, 1, 1) * s->normal.y + at(m, 1, 2) * s->normal.z,
                    at(m, 2, 0) * s->normal.x + at(m, 2, 1) * s->normal.y + at(m, 2, 2) * s->normal.z};
    }
}

template <class T>
[[gnu::always_inline]] inline void vertexv(const T* v, int n) {  // as addVertex
    if (!v) return;
    addVertex({static_cast<float>(v[0]), static_cast<float>(v[1]), n > 2 ? static_cast<float>(v[2]) : 0.0f,
               n > 3 ? static_cast<float>(v[3]) : 1.0f});
}

[[gnu::always_inline]] inline void setColor(const glm::vec4& c) {  // as addVertex
    Context::State* s = currentState();
    if (!s) return;
    s->color = c;
    if (s->insideBeginEnd) s->pipeline.colorPerVertex();
}

// Integer color components to float as the GL spec (and the reference) converts them.
float toFloat(GLubyte v) { return static_cast<float>(v) / 255.0f; }
float toFloat(GLushort v) { return static_cast<float>(v) * (1.0f / 65535.0f); }
float toFloat(GLuint v) { return static_cast<float>(static_cast<double>(v) * (1.0 / 4294967295.0)); }
float toFloat(GLbyte v) { return (2.0f * static_cast<float>(v) + 1.0f) * (1.0f / 255.0f); }
float toFloat(GLshort v) { return (2.0f * static_cast<float>(v) + 1.0f) * (1.0f / 65535.0f); }
float toFloat(GLint v) { return static_cast<float>((2.0 * v + 1.0) * (1.0 / 4294967295.0)); }
float toFloat(GLfloat v) { return v; }
float toFloat(GLdouble v) { return static_cast<float>(v); }

template <class T>
[[gnu::always_inline]] inline void colorv(const T* v, int n) {  // as addVertex
    if (v) setColor({toFloat(v[0]), toFloat(v[1]), toFloat(v[2]), n > 3 ? toFloat(v[3]) : 1.0f});
}

template <class T>
void normalv(const T* v) {
    if (Context::State* s = currentState(); s && v)
        s->normal = {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

template <class T>
void texCoordv(const T* v) {
    if (Context::State* s = currentState(); s && v)
        s->texCoord = {static_cast<float>(v[0]), static_cast<float>(v[1]), 0.0f, 1.0f};
}

void begin(GLenum mode) {
    Context::State* s = currentState();
    if (!s) return;
    if (mode > GL_POLYGON) return setError(*s, GL_INVALID_ENUM);
    if (s->insideBeginEnd) return setError(*s, GL_INVALID_OPERATION);
    drawCachedBitmaps(*s);
    if (s->modelviewProjectionStale) {
        s->modelviewProjection = multiply(s->projection.top(), s->modelview.top());
        s->modelviewProjectionStale = false;
    }
    s->insideBeginEnd = true;
    s->pipeline.beginPrimitive(s->draw, static_cast<glrenderer::PrimitiveMode>(mode));
}

void end() {
    Context::State* s = currentState();
    if (!s) return;
    if (!s->insideBeginEnd) return setError(*s, GL_INVALID_OPERATION);
    s->insideBeginEnd = false;
    s->pipeline.endPrimitive();
}

template <class T>
void rect(T x1, T y1, T x2, T y2) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    begin(GL_POLYGON);
    const float fx1 = static_cast<float>(x1), fy1 = static_cast<float>(y1);
    const float fx2 = static_cast<float>(x2), fy2 = static_cast<float>(y2);
    addVertex({fx1, fy1, 0, 1});
    addVertex({fx2, fy1, 0, 1});
    addVertex({fx2, fy2, 0, 1});
    addVertex({fx1, fy2, 0, 1});
    end();
}

// glColor, glNormal, ... in every type: one line per entry point.
#define MYGL_COLOR(suffix, T)                                                                    \
    {"glColor3" #suffix, entry(+[](T r, T g, T b) { colorv(std::array<T, 3>{r, g, b}.data(), 3); })},  \
    {"glColor4" #suffix, entry(+[](T r, T g, T b, T a) { colorv(std::array<T, 4>{r, g, b, a}.data(), 4); })}, \
    {"glColor3" #suffix "v", entry(+[](const T* v) { colorv(v, 3); })},                            \
    {"glColor4" #suffix "v", entry(+[](const T* v) { colorv(v, 4); })}
#define MYGL_NORMAL(suffix, T)                                                                    \
    {"glNormal3" #suffix, entry(+[](T x, T y, T z) { normalv(std::array<T, 3>{x, y, z}.data()); })},  \
    {"glNormal3" #suffix "v", entry(+[](const T* v) { normalv(v); })}
#define MYGL_TEXCOORD(suffix, T)                                                                  \
    {"glTexCoord2" #suffix, entry(+[](T s, T t) { texCoordv(std::array<T, 2>{s, t}.data()); })},     \
    {"glTexCoord2" #suffix "v", entry(+[](const T* v) { texCoordv(v); })}
#define MYGL_RECT(suffix, T)                                                                      \
    {"glRect" #suffix, entry(+[](T x1, T y1, T x2, T y2) { rect(x1, y1, x2, y2); })},               \
    {"glRect" #suffix "v", entry(+[](const T* a, const T* b) { if (a && b) rect(a[0], a[1], b[0], b[1]); })}

const EntryPoint kEntryPoints[] = {
    {"glBegin", entry(+[](GLenum mode) { begin(mode); })},
    {"glEnd", entry(+[] { end(); })},
    MYGL_POSITION_ENTRIES("glVertex", s, GLshort, vertexv), MYGL_POSITION_ENTRIES("glVertex", i, GLint, vertexv),
    MYGL_POSITION_ENTRIES("glVertex", f, GLfloat, vertexv), MYGL_POSITION_ENTRIES("glVertex", d, GLdouble, vertexv),
    MYGL_COLOR(b, GLbyte), MYGL_COLOR(ub, GLubyte), MYGL_COLOR(s, GLshort), MYGL_COLOR(us, GLushort),
    MYGL_COLOR(i, GLint), MYGL_COLOR(ui, GLuint), MYGL_COLOR(f, GLfloat), MYGL_COLOR(d, GLdouble),
    MYGL_NORMAL(b, GLbyte), MYGL_NORMAL(s, GLshort), MYGL_NORMAL(i, GLint), MYGL_NORMAL(f, GLfloat),
    MYGL_NORMAL(d, GLdouble),
    MYGL_TEXCOORD(s, GLshort), MYGL_TEXCOORD(i, GLint), MYGL_TEXCOORD(f, GLfloat), MYGL_TEXCOORD(d, GLdouble),
    MYGL_RECT(s, GLshort), MYGL_RECT(i, GLint), MYGL_RECT(f, GLfloat), MYGL_RECT(d, GLdouble),
    {"glEdgeFlag", entry(+[](GLboolean flag) {
         if (Context::State* s = currentState()) s->edgeFlag = flag != GL_FALSE;
     })},
    {"glEdgeFlagv", entry(+[](const GLboolean* flag) {
         if (Context::State* s = currentState(); s && flag) s->edgeFlag = *flag != GL_FALSE;
     })},
};

}  // namespace

std::span<const EntryPoint> beginEndEntryPoints() { return kEntryPoints; }

}  // namespace mygl
