// glTexGen and glGetTexGen, and the GL_TEXTURE_GEN_S/T/R/Q capabilities. As the reference: an
// eye plane is stored times the inverse of the modelview at the call.
#include "compiled.h"
#include "matrix_math.h"
#include "textures.h"

namespace mygl {
namespace {

// The index of GL_S ... GL_Q, or -1.
int coordinateIndex(GLenum coord) { return coord >= GL_S && coord <= GL_Q ? static_cast<int>(coord - GL_S) : -1; }

// The values glTexGen*v reads for `name` (the list's count rule).
std::size_t texGenCount(GLenum name) { return glcalls::texGenCount<GLdouble>(0, name, nullptr); }

// `count` values behind v: 1 for the scalar forms, which take only GL_TEXTURE_GEN_MODE.
void texGen(GLenum coord, GLenum name, const GLdouble* v, std::size_t count) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !v) return;
    const int i = coordinateIndex(coord);
    if (i < 0 || count < texGenCount(name)) return setError(*s, GL_INVALID_ENUM);
    const auto index = static_cast<std::size_t>(i);
    TextureUnit& unit = s->textures;
    switch (name) {
    case GL_TEXTURE_GEN_MODE: {
        const auto mode = static_cast<GLenum>(static_cast<GLint>(v[0]));
        const bool sphere = mode == GL_SPHERE_MAP;
        if ((mode != GL_OBJECT_LINEAR && mode != GL_EYE_LINEAR && !sphere) || (sphere && i > 1)) {
            return setError(*s, GL_INVALID_ENUM);
        }
        endBatch(*s);
        unit.genMode[index] = mode;
        unit.gen.mode[index] = mode == GL_OBJECT_LINEAR ? glrenderer::TexGenMode::ObjectLinear
                               : sphere                 ? glrenderer::TexGenMode::SphereMap
                                                        : glrenderer::TexGenMode::EyeLinear;
        return;
    }
    case GL_OBJECT_PLANE:
        endBatch(*s);
        unit.gen.objectPlane[index] = {float(v[0]), float(v[1]), float(v[2]), float(v[3])};
        return;
    case GL_EYE_PLANE:
        endBatch(*s);
        s->modelview.top().settleKind();
        unit.gen.eyePlane[index] =
            timesMatrix({float(v[0]), float(v[1]), float(v[2]), float(v[3])}, s->modelview.top().inverse());
        return;
    default: return setError(*s, GL_INVALID_ENUM);
    }
}

template <class T>
void texGenv(GLenum coord, GLenum name, const T* v) {
    if (!v) return;
    GLdouble values[4] = {};
    for (std::size_t i = 0; i < texGenCount(name); ++i) values[i] = static_cast<GLdouble>(v[i]);
    texGen(coord, name, values, texGenCount(name));
}

template <class T>
void getTexGen(GLenum coord, GLenum name, T* out) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    const int i = coordinateIndex(coord);
    if (i < 0) return setError(*s, GL_INVALID_ENUM);
    const auto index = static_cast<std::size_t>(i);
    const TextureUnit& unit = s->textures;
    if (name == GL_TEXTURE_GEN_MODE) {
        out[0] = static_cast<T>(unit.genMode[index]);
        return;
    }
    if (name != GL_OBJECT_PLANE && name != GL_EYE_PLANE) return setError(*s, GL_INVALID_ENUM);
    const glm::vec4& plane = name == GL_OBJECT_PLANE ? unit.gen.objectPlane[index] : unit.gen.eyePlane[index];
    for (int k = 0; k < 4; ++k) out[k] = static_cast<T>(plane[k]);
}

// clang-format off
#define MYGL_TEXGEN(suffix, T)                                                                                   \
    listed<gl::glTexGen##suffix, +[](GLenum c, GLenum n, T v) { const GLdouble d = v; texGen(c, n, &d, 1); }>(), \
    listed<gl::glTexGen##suffix##v, +[](GLenum c, GLenum n, const T* v) { texGenv(c, n, v); }>(),                \
    listed<gl::glGetTexGen##suffix##v, +[](GLenum c, GLenum n, T* out) { getTexGen(c, n, out); }>()
// clang-format on

const EntryPoint kEntryPoints[] = {
    MYGL_TEXGEN(i, GLint),
    MYGL_TEXGEN(f, GLfloat),
    MYGL_TEXGEN(d, GLdouble),
};

}  // namespace

bool setTexGenCapability(Context::State& s, GLenum cap, bool enabled) {
    if (cap < GL_TEXTURE_GEN_S || cap > GL_TEXTURE_GEN_Q) return false;
    const auto bit = static_cast<std::uint8_t>(1u << (cap - GL_TEXTURE_GEN_S));
    const std::uint8_t now = enabled ? s.textures.gen.enabled | bit : s.textures.gen.enabled & ~bit;
    if (now != s.textures.gen.enabled) endBatch(s);
    s.textures.gen.enabled = now;
    return true;
}

std::optional<bool> texGenCapability(const Context::State& s, GLenum cap) {
    if (cap < GL_TEXTURE_GEN_S || cap > GL_TEXTURE_GEN_Q) return std::nullopt;
    return (s.textures.gen.enabled >> (cap - GL_TEXTURE_GEN_S) & 1u) != 0;
}

std::span<const EntryPoint> textureGenEntryPoints() { return kEntryPoints; }

}  // namespace mygl
