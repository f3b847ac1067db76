// glPolygonOffset and the GL_POLYGON_OFFSET_FILL, _LINE and _POINT enables (issue 16).
#include "compiled.h"
#include "polygon_offset_state.h"

namespace mygl {
namespace {

void polygonOffset(GLfloat factor, GLfloat units) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    glrenderer::PolygonOffset& o = s->draw.edit().polygonOffset;
    if (o.factor != factor || o.units != units) endBatch(*s);
    o.factor = factor;
    o.units = units;
}

bool* enableOf(glrenderer::PolygonOffset& o, GLenum cap) {
    switch (cap) {
    case GL_POLYGON_OFFSET_FILL: return &o.fill;
    case GL_POLYGON_OFFSET_LINE: return &o.line;
    case GL_POLYGON_OFFSET_POINT: return &o.point;
    default: return nullptr;
    }
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glPolygonOffset, +[](GLfloat factor, GLfloat units) { polygonOffset(factor, units); }>(),
};

}  // namespace

bool setPolygonOffsetCapability(Context::State& state, GLenum cap, bool enabled) {
    bool* flag = enableOf(state.draw.edit().polygonOffset, cap);
    if (!flag) return false;
    if (*flag != enabled) endBatch(state);
    *flag = enabled;
    return true;
}

std::optional<bool> polygonOffsetCapability(const Context::State& state, GLenum cap) {
    glrenderer::PolygonOffset o = state.draw->polygonOffset;
    const bool* flag = enableOf(o, cap);
    return flag ? std::optional<bool>(*flag) : std::nullopt;
}

std::span<const EntryPoint> polygonOffsetEntryPoints() { return kEntryPoints; }

}  // namespace mygl
