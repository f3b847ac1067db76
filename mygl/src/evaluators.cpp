// Evaluators: glMap1/glMap2, glMapGrid, glEvalCoord, glEvalPoint, glEvalMesh, glGetMap and the
// GL_MAPn_* and GL_AUTO_NORMAL capabilities, as the reference runs them (Mesa's main/eval.c and
// its vertex buffer's evaluator paths): an evaluated vertex widens the vertex format with the
// maps' attributes, takes the evaluated colour, normal and texture coordinates, and leaves the
// current ones as they were.
#include "evaluators.h"

#include <cmath>
#include <optional>

#include "bezier.h"
#include "compiled.h"
#include "entry_points.h"
#include "vertex_input.h"

namespace mygl {
namespace {

constexpr int kComponents[kMapTargets] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

}  // namespace

// The initial maps: order 1, the attribute's default value.
Evaluators::Evaluators() {
    const float initial[kMapTargets][4] = {{1, 1, 1, 1}, {1},          {0, 0, 1}, {0},         {0, 0},
                                           {0, 0, 0},    {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0, 1}};
    for (int t = 0; t < kMapTargets; ++t) {
        map1[t].points.assign(initial[t], initial[t] + kComponents[t]);
        map2[t].points = map1[t].points;
    }
}

namespace {

using glrenderer::VertexAttribute;

// GL_MAP1_COLOR_4 ... GL_MAP1_VERTEX_4 and GL_MAP2_* are consecutive enums in that order.
std::optional<int> targetIndex(GLenum target, GLenum first) {
    if (target < first || target >= first + kMapTargets) return std::nullopt;
    return static_cast<int>(target - first);
}

// The map that gives an attribute, if one is enabled: texture coordinates and vertices take the
// most components enabled.
const Map* activeMap(const std::array<Map, kMapTargets>& maps, const std::array<bool, kMapTargets>& enabled,
                     std::initializer_list<MapTarget> byPriority, int& components) {
    for (MapTarget t : byPriority) {
        const auto i = static_cast<std::size_t>(t);
        if (enabled[i]) {
            components = kComponents[i];
            return &maps[i];
        }
    }
    return nullptr;
}

// An evaluated map's attributes for one glEvalCoord: the maps that take part and their sizes.
struct ActiveMaps {
    const Map* vertex = nullptr;
    const Map* normal = nullptr;
    const Map* color = nullptr;
    const Map* texture = nullptr;
    int vertexSize = 0, normalSize = 0, colorSize = 0, textureSize = 0;
};

ActiveMaps activeMaps(const std::array<Map, kMapTargets>& maps, const std::array<bool, kMapTargets>& enabled) {
    ActiveMaps a;
    a.vertex = activeMap(maps, enabled, {MapTarget::Vertex4, MapTarget::Vertex3}, a.vertexSize);
    a.normal = activeMap(maps, enabled, {MapTarget::Normal}, a.normalSize);
    a.color = activeMap(maps, enabled, {MapTarget::Color4}, a.colorSize);
    a.texture =
        activeMap(maps, enabled, {MapTarget::Texture4, MapTarget::Texture3, MapTarget::Texture2, MapTarget::Texture1},
                  a.textureSize);
    return a;
}

// The reference's vertex format grows with the maps' attributes first, in its attribute order.
void widenFormat(Context::State& s, const ActiveMaps& a, bool autoNormal) {
    if (a.vertex) s.pipeline.attribute(VertexAttribute::Position, a.vertexSize);
    if (a.normal) s.pipeline.attribute(VertexAttribute::Normal, a.normalSize);
    if (a.color) s.pipeline.attribute(VertexAttribute::Color, a.colorSize);
    if (a.texture) s.pipeline.attribute(VertexAttribute::TexCoord, a.textureSize);
    if (autoNormal) s.pipeline.attribute(VertexAttribute::Normal, 3);
}

// The current attributes an evaluated vertex changes, restored after it.
struct SavedAttributes {
    explicit SavedAttributes(Context::State& s)
        : s_(s), color_(s.color), vertexColor_(s.vertexColor), normal_(s.normal), texCoord_(s.texCoord) {}
    ~SavedAttributes() {
        s_.color = color_, s_.vertexColor = vertexColor_, s_.normal = normal_, s_.texCoord = texCoord_;
    }
    SavedAttributes(const SavedAttributes&) = delete;
    SavedAttributes& operator=(const SavedAttributes&) = delete;

private:
    Context::State& s_;
    glm::vec4 color_, vertexColor_;
    glm::vec3 normal_;
    glm::vec4 texCoord_;
};

// The evaluated attributes (missing components as (0, 0, 0, 1)) become the current ones.
template <class Evaluate>
void setEvaluatedAttributes(Context::State& s, const ActiveMaps& a, Evaluate&& evaluate) {
    if (a.normal) {
        const glm::vec4 n = evaluate(*a.normal, a.normalSize);
        s.normal = {n.x, n.y, n.z};
    }
    if (a.color) {
        s.color = evaluate(*a.color, a.colorSize);
        s.vertexColor = saturate(s.color);
        if (s.insideBeginEnd) s.pipeline.colorPerVertex();
    }
    if (a.texture) s.texCoord = evaluate(*a.texture, a.textureSize);
}

void evalCoord1(float u) {
    Context::State* s = currentState();
    if (!s) return;
    const Evaluators& e = s->evaluators;
    const ActiveMaps a = activeMaps(e.map1, e.enabled1);
    widenFormat(*s, a, false);
    const SavedAttributes saved(*s);
    const auto evaluate = [&](const Map& map, int size) {
        glm::vec4 out{0, 0, 0, 1};
        bezierCurve(map.points.data(), size, &out.x, (u - map.u1) * map.du, size, map.uorder);
        return out;
    };
    setEvaluatedAttributes(*s, a, evaluate);
    if (a.vertex) addVertex(evaluate(*a.vertex, a.vertexSize), a.vertexSize);
}

// Mesa's NORMALIZE_3FV: the squares summed in order, left alone when zero.
glm::vec3 normalized(glm::vec3 n) {
    const float lengthSquared = n.x * n.x + n.y * n.y + n.z * n.z;
    if (lengthSquared == 0.0f) return n;
    const float scale = 1.0f / std::sqrt(lengthSquared);
    return {n.x * scale, n.y * scale, n.z * scale};
}

void evalCoord2(float u, float v) {
    Context::State* s = currentState();
    if (!s) return;
    const Evaluators& e = s->evaluators;
    const ActiveMaps a = activeMaps(e.map2, e.enabled2);
    widenFormat(*s, a, e.autoNormal);
    const SavedAttributes saved(*s);
    const auto parameters = [&](const Map& map) { return std::pair{(u - map.u1) * map.du, (v - map.v1) * map.dv}; };
    const auto evaluate = [&](const Map& map, int size) {
        glm::vec4 out{0, 0, 0, 1};
        const auto [uu, vv] = parameters(map);
        bezierSurface(map.points.data(), &out.x, uu, vv, size, map.uorder, map.vorder);
        return out;
    };
    setEvaluatedAttributes(*s, a, evaluate);
    if (!a.vertex) return;
    if (!e.autoNormal) return addVertex(evaluate(*a.vertex, a.vertexSize), a.vertexSize);
    // GL_AUTO_NORMAL: the normal is the cross product of the partial derivatives (of the
    // projected surface for a 4-component map), normalized.
    glm::vec4 vertex{0, 0, 0, 1}, du{0.0f}, dv{0.0f};
    const auto [uu, vv] = parameters(*a.vertex);
    bezierSurfaceWithDerivatives(a.vertex->points.data(), &vertex.x, &du.x, &dv.x, uu, vv, a.vertexSize,
                                 a.vertex->uorder, a.vertex->vorder);
    if (a.vertexSize == 4) {
        for (int k = 0; k < 3; ++k) {
            du[k] = du[k] * vertex.w - du.w * vertex[k];
            dv[k] = dv[k] * vertex.w - dv.w * vertex[k];
        }
    }
    s->normal = normalized({du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x});
    addVertex(vertex, a.vertexSize);
}

template <class T>
void map1(GLenum target, T u1, T u2, GLint stride, GLint order, const T* points) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const auto fu1 = static_cast<float>(u1), fu2 = static_cast<float>(u2);
    if (fu1 == fu2 || order < 1 || order > kMaxEvalOrder || !points) return setError(*s, GL_INVALID_VALUE);
    const std::optional<int> t = targetIndex(target, GL_MAP1_COLOR_4);
    if (!t) return setError(*s, GL_INVALID_ENUM);
    const int size = kComponents[*t];
    if (stride < size) return setError(*s, GL_INVALID_VALUE);
    endBatch(*s);
    Map& map = s->evaluators.map1[static_cast<std::size_t>(*t)];
    map.points.clear();
    for (int i = 0; i < order; ++i) {
        for (int k = 0; k < size; ++k) map.points.push_back(static_cast<float>(points[std::ptrdiff_t(i) * stride + k]));
    }
    map.uorder = order;
    map.u1 = fu1, map.u2 = fu2;
    map.du = 1.0f / (fu2 - fu1);
}

template <class T>
void map2(GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2, GLint vstride, GLint vorder,
          const T* points) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const auto fu1 = static_cast<float>(u1), fu2 = static_cast<float>(u2);
    const auto fv1 = static_cast<float>(v1), fv2 = static_cast<float>(v2);
    if (fu1 == fu2 || fv1 == fv2 || uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 || vorder > kMaxEvalOrder) {
        return setError(*s, GL_INVALID_VALUE);
    }
    const std::optional<int> t = targetIndex(target, GL_MAP2_COLOR_4);
    if (!t) return setError(*s, GL_INVALID_ENUM);
    const int size = kComponents[*t];
    if (ustride < size || vstride < size) return setError(*s, GL_INVALID_VALUE);
    if (!points) return;  // the reference keeps no points then
    endBatch(*s);
    Map& map = s->evaluators.map2[static_cast<std::size_t>(*t)];
    map.points.clear();
    for (int i = 0; i < uorder; ++i) {
        for (int j = 0; j < vorder; ++j) {
            for (int k = 0; k < size; ++k) {
                map.points.push_back(
                    static_cast<float>(points[std::ptrdiff_t(i) * ustride + std::ptrdiff_t(j) * vstride + k]));
            }
        }
    }
    map.uorder = uorder, map.vorder = vorder;
    map.u1 = fu1, map.u2 = fu2, map.v1 = fv1, map.v2 = fv2;
    map.du = 1.0f / (fu2 - fu1);
    map.dv = 1.0f / (fv2 - fv1);
}

void mapGrid1(GLint un, float u1, float u2) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (un < 1) return setError(*s, GL_INVALID_VALUE);
    Evaluators& e = s->evaluators;
    e.grid1un = un, e.grid1u1 = u1, e.grid1u2 = u2;
    e.grid1du = (u2 - u1) / static_cast<float>(un);
}

void mapGrid2(GLint un, float u1, float u2, GLint vn, float v1, float v2) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (un < 1 || vn < 1) return setError(*s, GL_INVALID_VALUE);
    Evaluators& e = s->evaluators;
    e.grid2un = un, e.grid2u1 = u1, e.grid2u2 = u2;
    e.grid2du = (u2 - u1) / static_cast<float>(un);
    e.grid2vn = vn, e.grid2v1 = v1, e.grid2v2 = v2;
    e.grid2dv = (v2 - v1) / static_cast<float>(vn);
}

void evalPoint1(GLint i) {
    Context::State* s = currentState();
    if (!s) return;
    const Evaluators& e = s->evaluators;
    const float du = (e.grid1u2 - e.grid1u1) / static_cast<float>(e.grid1un);
    evalCoord1(static_cast<float>(i) * du + e.grid1u1);
}

void evalPoint2(GLint i, GLint j) {
    Context::State* s = currentState();
    if (!s) return;
    const Evaluators& e = s->evaluators;
    const float du = (e.grid2u2 - e.grid2u1) / static_cast<float>(e.grid2un);
    const float dv = (e.grid2v2 - e.grid2v1) / static_cast<float>(e.grid2vn);
    evalCoord2(static_cast<float>(i) * du + e.grid2u1, static_cast<float>(j) * dv + e.grid2v1);
}

bool vertexMapEnabled(const std::array<bool, kMapTargets>& enabled) {
    return enabled[static_cast<std::size_t>(MapTarget::Vertex3)] ||
           enabled[static_cast<std::size_t>(MapTarget::Vertex4)];
}

// The grid's parameters step by repeated addition, as the reference's loops do.
void evalMesh1(GLenum mode, GLint i1, GLint i2) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_POINT && mode != GL_LINE) return setError(*s, GL_INVALID_ENUM);
    const Evaluators& e = s->evaluators;
    if (!vertexMapEnabled(e.enabled1)) return;
    const float du = e.grid1du;
    float u = e.grid1u1 + static_cast<float>(i1) * du;
    begin(mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP, quadSplitOf(*s));
    for (GLint i = i1; i <= i2; ++i, u += du) evalCoord1(u);
    end();
}

void evalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return setError(*s, GL_INVALID_ENUM);
    const Evaluators& e = s->evaluators;
    if (!vertexMapEnabled(e.enabled2)) return;
    const float du = e.grid2du, dv = e.grid2dv;
    const float v1 = e.grid2v1 + static_cast<float>(j1) * dv, u1 = e.grid2u1 + static_cast<float>(i1) * du;
    const glrenderer::QuadSplit split = quadSplitOf(*s);
    float u = u1, v = v1;
    switch (mode) {
    case GL_POINT:
        begin(GL_POINTS, split);
        v = v1;
        for (GLint j = j1; j <= j2; ++j, v += dv) {
            u = u1;
            for (GLint i = i1; i <= i2; ++i, u += du) evalCoord2(u, v);
        }
        end();
        break;
    case GL_LINE:
        v = v1;
        for (GLint j = j1; j <= j2; ++j, v += dv) {
            begin(GL_LINE_STRIP, split);
            u = u1;
            for (GLint i = i1; i <= i2; ++i, u += du) evalCoord2(u, v);
            end();
        }
        u = u1;
        for (GLint i = i1; i <= i2; ++i, u += du) {
            begin(GL_LINE_STRIP, split);
            v = v1;
            for (GLint j = j1; j <= j2; ++j, v += dv) evalCoord2(u, v);
            end();
        }
        break;
    default:
        v = v1;
        for (GLint j = j1; j < j2; ++j, v += dv) {
            begin(GL_TRIANGLE_STRIP, split);
            u = u1;
            for (GLint i = i1; i <= i2; ++i, u += du) {
                evalCoord2(u, v);
                evalCoord2(u, v + dv);
            }
            end();
        }
        break;
    }
}

// glGetMap: GL_COEFF (the copied points), GL_ORDER, GL_DOMAIN, converted by `convert`.
template <class T, class Convert>
void getMap(GLenum target, GLenum query, T* out, Convert convert) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    const std::optional<int> t1 = targetIndex(target, GL_MAP1_COLOR_4), t2 = targetIndex(target, GL_MAP2_COLOR_4);
    if (!t1 && !t2) return setError(*s, GL_INVALID_ENUM);
    const Map& map =
        t1 ? s->evaluators.map1[static_cast<std::size_t>(*t1)] : s->evaluators.map2[static_cast<std::size_t>(*t2)];
    switch (query) {
    case GL_COEFF:
        for (std::size_t i = 0; i < map.points.size(); ++i) out[i] = convert(map.points[i]);
        break;
    case GL_ORDER:
        out[0] = static_cast<T>(map.uorder);
        if (t2) out[1] = static_cast<T>(map.vorder);
        break;
    case GL_DOMAIN:
        out[0] = convert(map.u1), out[1] = convert(map.u2);
        if (t2) out[2] = convert(map.v1), out[3] = convert(map.v2);
        break;
    default: setError(*s, GL_INVALID_ENUM);
    }
}

GLint roundToInt(float x) { return static_cast<GLint>(std::lround(x)); }

const EntryPoint kEntryPoints[] = {
    listed<gl::glMap1f, +[](GLenum t, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                            const GLfloat* p) { map1(t, u1, u2, stride, order, p); }>(),
    listed<gl::glMap1d, +[](GLenum t, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                            const GLdouble* p) { map1(t, u1, u2, stride, order, p); }>(),
    listed<gl::glMap2f, +[](GLenum t, GLfloat u1, GLfloat u2, GLint us, GLint uo, GLfloat v1, GLfloat v2, GLint vs,
                            GLint vo, const GLfloat* p) { map2(t, u1, u2, us, uo, v1, v2, vs, vo, p); }>(),
    listed<gl::glMap2d, +[](GLenum t, GLdouble u1, GLdouble u2, GLint us, GLint uo, GLdouble v1, GLdouble v2, GLint vs,
                            GLint vo, const GLdouble* p) { map2(t, u1, u2, us, uo, v1, v2, vs, vo, p); }>(),
    listed<gl::glMapGrid1f, +[](GLint un, GLfloat u1, GLfloat u2) { mapGrid1(un, u1, u2); }>(),
    listed<gl::glMapGrid1d,
           +[](GLint un, GLdouble u1, GLdouble u2) { mapGrid1(un, static_cast<float>(u1), static_cast<float>(u2)); }>(),
    listed<gl::glMapGrid2f, +[](GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1,
                                GLfloat v2) { mapGrid2(un, u1, u2, vn, v1, v2); }>(),
    listed<gl::glMapGrid2d,
           +[](GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2) {
               mapGrid2(un, static_cast<float>(u1), static_cast<float>(u2), vn, static_cast<float>(v1),
                        static_cast<float>(v2));
           }>(),
    listed<gl::glEvalCoord1f, +[](GLfloat u) { evalCoord1(u); }>(),
    listed<gl::glEvalCoord1d, +[](GLdouble u) { evalCoord1(static_cast<float>(u)); }>(),
    listed<gl::glEvalCoord1fv,
           +[](const GLfloat* u) {
               if (u) evalCoord1(u[0]);
           }>(),
    listed<gl::glEvalCoord1dv,
           +[](const GLdouble* u) {
               if (u) evalCoord1(static_cast<float>(u[0]));
           }>(),
    listed<gl::glEvalCoord2f, +[](GLfloat u, GLfloat v) { evalCoord2(u, v); }>(),
    listed<gl::glEvalCoord2d,
           +[](GLdouble u, GLdouble v) { evalCoord2(static_cast<float>(u), static_cast<float>(v)); }>(),
    listed<gl::glEvalCoord2fv,
           +[](const GLfloat* u) {
               if (u) evalCoord2(u[0], u[1]);
           }>(),
    listed<gl::glEvalCoord2dv,
           +[](const GLdouble* u) {
               if (u) evalCoord2(static_cast<float>(u[0]), static_cast<float>(u[1]));
           }>(),
    listed<gl::glEvalPoint1, +[](GLint i) { evalPoint1(i); }>(),
    listed<gl::glEvalPoint2, +[](GLint i, GLint j) { evalPoint2(i, j); }>(),
    listed<gl::glEvalMesh1, +[](GLenum mode, GLint i1, GLint i2) { evalMesh1(mode, i1, i2); }>(),
    listed<gl::glEvalMesh2,
           +[](GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) { evalMesh2(mode, i1, i2, j1, j2); }>(),
    listed<gl::glGetMapdv,
           +[](GLenum t, GLenum q, GLdouble* v) { getMap(t, q, v, [](float x) { return double(x); }); }>(),
    listed<gl::glGetMapfv, +[](GLenum t, GLenum q, GLfloat* v) { getMap(t, q, v, [](float x) { return x; }); }>(),
    listed<gl::glGetMapiv, +[](GLenum t, GLenum q, GLint* v) { getMap(t, q, v, roundToInt); }>(),
};

}  // namespace

std::span<const EntryPoint> evaluatorEntryPoints() { return kEntryPoints; }

bool setEvaluatorCapability(Context::State& s, GLenum cap, bool enabled) {
    Evaluators& e = s.evaluators;
    bool* flag = cap == GL_AUTO_NORMAL ? &e.autoNormal : nullptr;
    if (const std::optional<int> t = targetIndex(cap, GL_MAP1_COLOR_4))
        flag = &e.enabled1[static_cast<std::size_t>(*t)];
    if (const std::optional<int> t = targetIndex(cap, GL_MAP2_COLOR_4))
        flag = &e.enabled2[static_cast<std::size_t>(*t)];
    if (!flag) return false;
    if (*flag != enabled) endBatch(s);
    *flag = enabled;
    return true;
}

std::optional<bool> evaluatorCapability(const Context::State& s, GLenum cap) {
    const Evaluators& e = s.evaluators;
    if (cap == GL_AUTO_NORMAL) return e.autoNormal;
    if (const std::optional<int> t = targetIndex(cap, GL_MAP1_COLOR_4)) return e.enabled1[static_cast<std::size_t>(*t)];
    if (const std::optional<int> t = targetIndex(cap, GL_MAP2_COLOR_4)) return e.enabled2[static_cast<std::size_t>(*t)];
    return std::nullopt;
}

}  // namespace mygl
