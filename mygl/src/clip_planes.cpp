// glClipPlane and GL_CLIP_PLANEi. As the reference: the equation (in float) is taken to eye space
// by the inverse of the modelview at the call, and to clip space by the inverse of the
// projection when the plane is enabled or the projection changes; the pipeline clips with the
// clip-space planes (DrawState::clipPlanes).
#include "compiled.h"
#include "matrix_math.h"
#include "entry_points.h"

namespace mygl {
namespace {

constexpr int kPlanes = static_cast<int>(std::tuple_size_v<decltype(glrenderer::UserClipPlanes::planes)>);

// The index of GL_CLIP_PLANEi, or nullopt.
std::optional<std::size_t> planeIndex(GLenum plane) {
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kPlanes) return std::nullopt;
    return plane - GL_CLIP_PLANE0;
}

void updateClipPlane(Context::State& s, std::size_t i, const Matrix& projectionInverse) {
    s.draw.edit().clipPlanes.planes[i] = timesMatrix(s.eyeClipPlanes[i], projectionInverse);
}

Matrix projectionInverse(Context::State& s) {
    s.projection.top().settleKind();
    return s.projection.top().inverse();
}

void clipPlane(GLenum plane, const GLdouble* equation) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !equation) return;
    const std::optional<std::size_t> i = planeIndex(plane);
    if (!i) return setError(*s, GL_INVALID_ENUM);
    endBatch(*s);
    const glm::vec4 given{float(equation[0]), float(equation[1]), float(equation[2]), float(equation[3])};
    s->modelview.top().settleKind();
    s->eyeClipPlanes[*i] = timesMatrix(given, s->modelview.top().inverse());
    if (s->draw->clipPlanes.enabled >> *i & 1u) updateClipPlane(*s, *i, projectionInverse(*s));
}

void getClipPlane(GLenum plane, GLdouble* out) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    const std::optional<std::size_t> i = planeIndex(plane);
    if (!i) return setError(*s, GL_INVALID_ENUM);
    for (int k = 0; k < 4; ++k) out[k] = s->eyeClipPlanes[*i][k];
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glClipPlane, +[](GLenum plane, const GLdouble* equation) { clipPlane(plane, equation); }>(),
    listed<gl::glGetClipPlane, +[](GLenum plane, GLdouble* out) { getClipPlane(plane, out); }>(),
};

}  // namespace

std::span<const EntryPoint> clipPlaneEntryPoints() { return kEntryPoints; }

bool setClipPlaneCapability(Context::State& s, GLenum cap, bool enabled) {
    const std::optional<std::size_t> i = planeIndex(cap);
    if (!i) return false;
    const auto bit = static_cast<std::uint8_t>(1u << *i);
    std::uint8_t& mask = s.draw.edit().clipPlanes.enabled;
    if (((mask & bit) != 0) == enabled) return true;
    endBatch(s);
    mask = static_cast<std::uint8_t>(enabled ? mask | bit : mask & ~bit);
    if (enabled) updateClipPlane(s, *i, projectionInverse(s));
    return true;
}

std::optional<bool> clipPlaneCapability(const Context::State& s, GLenum cap) {
    const std::optional<std::size_t> i = planeIndex(cap);
    if (!i) return std::nullopt;
    return (s.draw->clipPlanes.enabled >> *i & 1u) != 0;
}

void updateClipPlanes(Context::State& s) {
    if (!s.draw->clipPlanes.enabled) return;
    const Matrix inverse = projectionInverse(s);
    for (std::size_t i = 0; i < kPlanes; ++i) {
        if (s.draw->clipPlanes.enabled >> i & 1u) updateClipPlane(s, i, inverse);
    }
}

}  // namespace mygl
