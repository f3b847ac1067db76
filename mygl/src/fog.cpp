// glFog{f,i}[v] and GL_FOG: the state as GL keeps it (for glGet), and the pipeline's FogState
// formed from it.
#include <algorithm>

#include "compiled.h"
#include "fog_state.h"

namespace mygl {
namespace {

using glrenderer::FogMode;

// The GL value of a fog parameter's integer form: colours map the integer range onto [-1, 1]
// (the reference's INT_TO_FLOAT), everything else converts as it is.
float intParameter(GLenum name, GLint value) {
    if (name == GL_FOG_COLOR) return static_cast<float>((2.0 * value + 1.0) * (1.0 / 4294967294.0));
    return static_cast<float>(value);
}

// glFogfv with `count` values behind `p` (1, or 4 for the vector forms); records the spec's
// errors: an unknown name or mode, a negative density, a colour through a scalar form.
void fog(GLenum name, const GLfloat* p, int count) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !p) return;
    FogParameters& f = s->fog;
    switch (name) {
    case GL_FOG_MODE: {
        const auto mode = static_cast<GLenum>(static_cast<GLint>(p[0]));
        if (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2) return setError(*s, GL_INVALID_ENUM);
        f.mode = mode;
        break;
    }
    case GL_FOG_DENSITY:
        if (p[0] < 0.0f) return setError(*s, GL_INVALID_VALUE);
        f.density = p[0];
        break;
    case GL_FOG_START: f.start = p[0]; break;
    case GL_FOG_END: f.end = p[0]; break;
    case GL_FOG_INDEX: f.index = p[0]; break;
    case GL_FOG_COLOR:
        if (count != 4) return setError(*s, GL_INVALID_ENUM);
        for (int i = 0; i < 4; ++i) f.color[i] = std::clamp(p[i], 0.0f, 1.0f);
        break;
    default: return setError(*s, GL_INVALID_ENUM);
    }
    updateFog(*s);
}

void fogi(GLenum name, const GLint* p, int count) {
    if (!p) return;
    GLfloat values[4] = {};
    for (int i = 0; i < count; ++i) values[i] = intParameter(name, p[i]);
    fog(name, values, count);
}

// How many values the vector forms read for `name`.
const EntryPoint kEntryPoints[] = {
    listed<gl::glFogf, +[](GLenum name, GLfloat v) { fog(name, &v, 1); }>(),
    listed<gl::glFogi, +[](GLenum name, GLint v) { fogi(name, &v, 1); }>(),
    listed<gl::glFogfv,
           +[](GLenum name, const GLfloat* v) { fog(name, v, static_cast<int>(glcalls::fogCount(name, v))); }>(),
    listed<gl::glFogiv,
           +[](GLenum name, const GLint* v) { fogi(name, v, static_cast<int>(glcalls::fogCount(name, v))); }>(),
};

}  // namespace

void updateFog(Context::State& s) {
    const FogParameters& f = s.fog;
    const FogMode mode = !f.enabled            ? FogMode::Off
                         : f.mode == GL_LINEAR ? FogMode::Linear
                         : f.mode == GL_EXP    ? FogMode::Exp
                                               : FogMode::Exp2;
    const glrenderer::FogState fog =
        glrenderer::makeFogState(mode, s.draw->fog.distance, f.density, f.start, f.end, f.color);
    if (fog != s.draw->fog) endBatch(s);
    s.draw.edit().fog = fog;
}

void updateFogDistance(Context::State& s) {
    // The reference's vertex program reuses the eye position when lighting computed it.
    bool eyePosition = false;
    if (s.lightingEnabled) {
        eyePosition = s.lighting.localViewer;
        for (const glrenderer::LightSource& l : s.lighting.lights)
            eyePosition = eyePosition || (l.enabled && l.position.w != 0.0f);
    }
    s.draw.edit().fog.distance =
        eyePosition ? glrenderer::FogDistance::EyePosition : glrenderer::FogDistance::OwnDotProduct;
}

std::optional<std::vector<double>> fogQuery(const Context::State& s, GLenum name) {
    const FogParameters& f = s.fog;
    switch (name) {
    case GL_FOG_MODE: return std::vector<double>{double(f.mode)};
    case GL_FOG_DENSITY: return std::vector<double>{f.density};
    case GL_FOG_START: return std::vector<double>{f.start};
    case GL_FOG_END: return std::vector<double>{f.end};
    case GL_FOG_INDEX: return std::vector<double>{f.index};
    case GL_FOG_COLOR: return std::vector<double>{f.color.r, f.color.g, f.color.b, f.color.a};
    default: return std::nullopt;
    }
}

std::span<const EntryPoint> fogEntryPoints() { return kEntryPoints; }

}  // namespace mygl
