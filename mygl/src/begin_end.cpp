// glBegin/glEnd and the per-vertex calls: vertices go to the pipeline as given, whose vertex
// stage transforms and lights them.
#include <array>

#include "compiled.h"
#include "fog_state.h"
#include "textures.h"
#include "vertex_input.h"

namespace mygl {

void begin(GLenum mode, glrenderer::QuadSplit quadSplit) {
    Context::State* s = currentState();
    if (!s) return;
    if (s->insideBeginEnd) return setError(*s, GL_INVALID_OPERATION);  // before the mode, as every call inside
    if (mode > GL_POLYGON) return setError(*s, GL_INVALID_ENUM);
    drawCachedBitmaps(*s);  // the reference draws its bitmap cache before any draw
    s->updateModelviewProjection();
    if (s->clipPlanesStale) {
        s->clipPlanesStale = false;
        updateClipPlanes(*s);
    }
    prepareLighting(*s);
    if (s->fog.enabled) updateFogDistance(*s);
    updateTexturing(*s);
    s->insideBeginEnd = true;
    s->pipeline.beginPrimitive(s->draw.interned(s->pipeline), static_cast<glrenderer::PrimitiveMode>(mode), quadSplit);
    if (s->lightingEnabled) s->pipeline.colorPerVertex();  // lit colours vary per vertex
}

void end() {
    Context::State* s = currentState();
    if (!s) return;
    if (!s->insideBeginEnd) return setError(*s, GL_INVALID_OPERATION);
    s->insideBeginEnd = false;
    s->pipeline.endPrimitive();
    if (s->lightingOnProgramThread) {  // the pipeline's batches take the material as it is now
        s->lightingOnProgramThread = false;
        s->lightingStale = true;
    }
}

namespace {

// glRect is the quad (x1,y1) (x2,y1) (x2,y2) (x1,y2), as the reference issues it.
template <class T>
void rect(T x1, T y1, T x2, T y2) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    begin(GL_QUADS, quadSplitOf(*s));
    const float fx1 = static_cast<float>(x1), fy1 = static_cast<float>(y1);
    const float fx2 = static_cast<float>(x2), fy2 = static_cast<float>(y2);
    addVertex({fx1, fy1, 0, 1}, 2);
    addVertex({fx2, fy1, 0, 1}, 2);
    addVertex({fx2, fy2, 0, 1}, 2);
    addVertex({fx1, fy2, 0, 1}, 2);
    end();
}

// glColor, glNormal, ... in every type: one line per entry point.
// clang-format off
#define MYGL_COLOR(suffix, T)                                                                                    \
    listed<gl::glColor3##suffix, +[](T r, T g, T b) { colorv(std::array<T, 3>{r, g, b}.data(), 3); }>(),         \
    listed<gl::glColor4##suffix, +[](T r, T g, T b, T a) { colorv(std::array<T, 4>{r, g, b, a}.data(), 4); }>(), \
    listed<gl::glColor3##suffix##v, +[](const T* v) { colorv(v, 3); }>(),                                        \
    listed<gl::glColor4##suffix##v, +[](const T* v) { colorv(v, 4); }>()
#define MYGL_NORMAL(suffix, T)                                                                          \
    listed<gl::glNormal3##suffix, +[](T x, T y, T z) { normalv(std::array<T, 3>{x, y, z}.data()); }>(), \
    listed<gl::glNormal3##suffix##v, +[](const T* v) { normalv(v); }>()
#define MYGL_TEXCOORD(suffix, T)                                                                                       \
    listed<gl::glTexCoord1##suffix, +[](T s) { texCoordv(&s, 1); }>(),                                                 \
    listed<gl::glTexCoord2##suffix, +[](T s, T t) { texCoordv(std::array<T, 2>{s, t}.data(), 2); }>(),                 \
    listed<gl::glTexCoord3##suffix, +[](T s, T t, T r) { texCoordv(std::array<T, 3>{s, t, r}.data(), 3); }>(),         \
    listed<gl::glTexCoord4##suffix, +[](T s, T t, T r, T q) { texCoordv(std::array<T, 4>{s, t, r, q}.data(), 4); }>(), \
    listed<gl::glTexCoord1##suffix##v, +[](const T* v) { texCoordv(v, 1); }>(),                                        \
    listed<gl::glTexCoord2##suffix##v, +[](const T* v) { texCoordv(v, 2); }>(),                                        \
    listed<gl::glTexCoord3##suffix##v, +[](const T* v) { texCoordv(v, 3); }>(),                                        \
    listed<gl::glTexCoord4##suffix##v, +[](const T* v) { texCoordv(v, 4); }>()
#define MYGL_RECT(suffix, T)                                                             \
    listed<gl::glRect##suffix, +[](T x1, T y1, T x2, T y2) { rect(x1, y1, x2, y2); }>(), \
    listed<gl::glRect##suffix##v, +[](const T* a, const T* b) { if (a && b) rect(a[0], a[1], b[0], b[1]); }>()
// clang-format on

const EntryPoint kEntryPoints[] = {
    listed<gl::glBegin,
           +[](GLenum mode) {
               if (Context::State* s = currentState()) begin(mode, quadSplitOf(*s));
           }>(),
    listed<gl::glEnd, +[] { end(); }>(),
    MYGL_POSITION_ENTRIES(glVertex, s, GLshort, vertexv),
    MYGL_POSITION_ENTRIES(glVertex, i, GLint, vertexv),
    MYGL_POSITION_ENTRIES(glVertex, f, GLfloat, vertexv),
    MYGL_POSITION_ENTRIES(glVertex, d, GLdouble, vertexv),
    MYGL_COLOR(b, GLbyte),
    MYGL_COLOR(ub, GLubyte),
    MYGL_COLOR(s, GLshort),
    MYGL_COLOR(us, GLushort),
    MYGL_COLOR(i, GLint),
    MYGL_COLOR(ui, GLuint),
    MYGL_COLOR(f, GLfloat),
    MYGL_COLOR(d, GLdouble),
    MYGL_NORMAL(b, GLbyte),
    MYGL_NORMAL(s, GLshort),
    MYGL_NORMAL(i, GLint),
    MYGL_NORMAL(f, GLfloat),
    MYGL_NORMAL(d, GLdouble),
    MYGL_TEXCOORD(s, GLshort),
    MYGL_TEXCOORD(i, GLint),
    MYGL_TEXCOORD(f, GLfloat),
    MYGL_TEXCOORD(d, GLdouble),
    MYGL_RECT(s, GLshort),
    MYGL_RECT(i, GLint),
    MYGL_RECT(f, GLfloat),
    MYGL_RECT(d, GLdouble),
    listed<gl::glEdgeFlag, +[](GLboolean flag) { setEdgeFlag(flag != GL_FALSE); }>(),
    listed<gl::glEdgeFlagv,
           +[](const GLboolean* flag) {
               if (flag) setEdgeFlag(*flag != GL_FALSE);
           }>(),
};

}  // namespace

std::span<const EntryPoint> beginEndEntryPoints() { return kEntryPoints; }

}  // namespace mygl
