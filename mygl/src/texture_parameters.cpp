// glTexParameter, glTexEnv and the texture queries (glGetTexParameter, glGetTexLevelParameter,
// glGetTexEnv, glGetTexImage), the GL_TEXTURE_1D/2D capabilities, and the pipeline's texture
// state formed from them.
#include <algorithm>
#include <cmath>

#include "compiled.h"
#include "pixel_pack.h"
#include "texture_images.h"
#include "textures.h"

namespace mygl {
namespace {

using glrenderer::TextureBase;

bool isMipmapFilter(GLenum filter) { return filter != GL_NEAREST && filter != GL_LINEAR; }

// How many levels a texture samples: 1 without a mipmap filter, else every level down to
// 1 x 1, each half the one above in the same internal format; 0 when they are not all there
// (the texture is incomplete: texturing is off).
std::size_t sampledLevels(const TextureObject& t) {
    const TextureLevel& base = t.levels[0];
    if (!base.defined || base.imageWidth == 0 || base.imageHeight == 0) return 0;
    if (!isMipmapFilter(t.minFilter)) return 1;
    int width = base.imageWidth, height = base.imageHeight;
    std::size_t level = 1;
    for (; width > 1 || height > 1; ++level) {
        width = std::max(width / 2, 1), height = std::max(height / 2, 1);
        const TextureLevel& l = t.levels[level];
        if (!l.defined || l.imageWidth != width || l.imageHeight != height || l.internalFormat != base.internalFormat) {
            return 0;
        }
    }
    return level;
}

glrenderer::TextureEnv envOf(GLenum mode) {
    switch (mode) {
    case GL_REPLACE: return glrenderer::TextureEnv::Replace;
    case GL_DECAL: return glrenderer::TextureEnv::Decal;
    case GL_BLEND: return glrenderer::TextureEnv::Blend;
    case GL_ADD: return glrenderer::TextureEnv::Add;
    default: return glrenderer::TextureEnv::Modulate;
    }
}

bool isTextureTarget(GLenum target) { return target == GL_TEXTURE_1D || target == GL_TEXTURE_2D; }

// glTexParameter with `count` values; the spec's errors for unknown names and values.
void texParameter(GLenum target, GLenum name, const GLfloat* v, int count) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !v) return;
    if (!isTextureTarget(target)) return setError(*s, GL_INVALID_ENUM);
    TextureObject& t = boundTexture(s->textures, target);
    const auto value = static_cast<GLenum>(static_cast<GLint>(v[0]));
    switch (name) {
    case GL_TEXTURE_MIN_FILTER:
        if (value != GL_NEAREST && value != GL_LINEAR && value != GL_NEAREST_MIPMAP_NEAREST &&
            value != GL_LINEAR_MIPMAP_NEAREST && value != GL_NEAREST_MIPMAP_LINEAR &&
            value != GL_LINEAR_MIPMAP_LINEAR) {
            return setError(*s, GL_INVALID_ENUM);
        }
        t.minFilter = value;
        return;
    case GL_TEXTURE_MAG_FILTER:
        if (value != GL_NEAREST && value != GL_LINEAR) return setError(*s, GL_INVALID_ENUM);
        t.magFilter = value;
        return;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
        if (value != GL_REPEAT && value != GL_CLAMP && value != GL_CLAMP_TO_EDGE) return setError(*s, GL_INVALID_ENUM);
        (name == GL_TEXTURE_WRAP_S ? t.wrapS : t.wrapT) = value;
        return;
    case GL_TEXTURE_BORDER_COLOR:
        if (count != 4) return setError(*s, GL_INVALID_ENUM);
        for (int i = 0; i < 4; ++i) t.borderColor[i] = std::clamp(v[i], 0.0f, 1.0f);
        return;
    case GL_TEXTURE_PRIORITY: t.priority = std::clamp(v[0], 0.0f, 1.0f); return;
    default: return setError(*s, GL_INVALID_ENUM);
    }
}

// Integer forms: colours map the integer range onto [-1, 1]; enums and priorities convert as they are.
void texParameteri(GLenum target, GLenum name, const GLint* v, int count) {
    if (!v) return;
    GLfloat values[4] = {};
    for (int i = 0; i < count; ++i) {
        values[i] = name == GL_TEXTURE_BORDER_COLOR ? static_cast<float>((2.0 * v[i] + 1.0) / 4294967294.0)
                                                    : static_cast<float>(v[i]);
    }
    texParameter(target, name, values, count);
}

void texEnv(GLenum target, GLenum name, const GLfloat* v, int count) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !v) return;
    if (target != GL_TEXTURE_ENV) return setError(*s, GL_INVALID_ENUM);
    TextureUnit& unit = s->textures;
    if (name == GL_TEXTURE_ENV_MODE) {
        const auto mode = static_cast<GLenum>(static_cast<GLint>(v[0]));
        if (mode != GL_MODULATE && mode != GL_DECAL && mode != GL_BLEND && mode != GL_REPLACE && mode != GL_ADD) {
            return setError(*s, GL_INVALID_ENUM);
        }
        unit.envMode = mode;
        return;
    }
    if (name == GL_TEXTURE_ENV_COLOR && count == 4) {
        for (int i = 0; i < 4; ++i) unit.envColor[i] = std::clamp(v[i], 0.0f, 1.0f);
        return;
    }
    setError(*s, GL_INVALID_ENUM);
}

void texEnvi(GLenum target, GLenum name, const GLint* v, int count) {
    if (!v) return;
    GLfloat values[4] = {};
    for (int i = 0; i < count; ++i) {
        values[i] = name == GL_TEXTURE_ENV_COLOR ? static_cast<float>((2.0 * v[i] + 1.0) / 4294967294.0)
                                                 : static_cast<float>(v[i]);
    }
    texEnv(target, name, values, count);
}

// The values of a query and whether they are a colour (integer forms scale colours).
struct Answer {
    std::vector<double> values;
    bool color = false;
};

template <class T>
void answer(const Answer& a, T* out) {
    for (std::size_t i = 0; i < a.values.size(); ++i) {
        if constexpr (std::is_same_v<T, GLint>) {
            out[i] = a.color ? static_cast<GLint>(std::clamp(a.values[i], -1.0, 1.0) * 2147483647.0)
                             : static_cast<GLint>(std::lround(a.values[i]));
        } else {
            out[i] = static_cast<T>(a.values[i]);
        }
    }
}

template <class T>
void getTexParameter(GLenum target, GLenum name, T* out) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    if (!isTextureTarget(target)) return setError(*s, GL_INVALID_ENUM);
    const TextureObject& t = boundTexture(s->textures, target);
    Answer a;
    switch (name) {
    case GL_TEXTURE_MIN_FILTER: a.values = {double(t.minFilter)}; break;
    case GL_TEXTURE_MAG_FILTER: a.values = {double(t.magFilter)}; break;
    case GL_TEXTURE_WRAP_S: a.values = {double(t.wrapS)}; break;
    case GL_TEXTURE_WRAP_T: a.values = {double(t.wrapT)}; break;
    case GL_TEXTURE_BORDER_COLOR:
        a = {{t.borderColor.r, t.borderColor.g, t.borderColor.b, t.borderColor.a}, true};
        break;
    case GL_TEXTURE_PRIORITY: a.values = {t.priority}; break;
    case GL_TEXTURE_RESIDENT: a.values = {1.0}; break;
    default: return setError(*s, GL_INVALID_ENUM);
    }
    answer(a, out);
}

// The bits of each component a level's internal format stores: 8 where its base has it.
double componentBits(const TextureLevel& level, GLenum name) {
    const TextureBase base = level.base;
    const bool color = base == TextureBase::Rgb || base == TextureBase::Rgba;
    const bool alpha = base == TextureBase::Alpha || base == TextureBase::LuminanceAlpha || base == TextureBase::Rgba;
    const bool luminance = base == TextureBase::Luminance || base == TextureBase::LuminanceAlpha;
    switch (name) {
    case GL_TEXTURE_RED_SIZE:
    case GL_TEXTURE_GREEN_SIZE:
    case GL_TEXTURE_BLUE_SIZE: return color ? 8 : 0;
    case GL_TEXTURE_ALPHA_SIZE: return alpha ? 8 : 0;
    case GL_TEXTURE_LUMINANCE_SIZE: return luminance ? 8 : 0;
    default: return base == TextureBase::Intensity ? 8 : 0;  // GL_TEXTURE_INTENSITY_SIZE
    }
}

template <class T>
void getTexLevelParameter(GLenum target, GLint level, GLenum name, T* out) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (!isTextureTarget(target) && target != GL_PROXY_TEXTURE_1D && target != GL_PROXY_TEXTURE_2D) {
        return setError(*s, GL_INVALID_ENUM);
    }
    if (level < 0 || level >= kMaxTextureLevels) return setError(*s, GL_INVALID_VALUE);
    const TextureLevel& l = boundTexture(s->textures, target).levels[static_cast<std::size_t>(level)];
    const bool defined = l.width > 0;
    Answer a;
    switch (name) {
    case GL_TEXTURE_WIDTH: a.values = {double(l.width)}; break;
    case GL_TEXTURE_HEIGHT: a.values = {double(l.height)}; break;
    case GL_TEXTURE_BORDER: a.values = {double(l.border)}; break;
    case GL_TEXTURE_INTERNAL_FORMAT: a.values = {double(defined ? l.internalFormat : 1)}; break;
    case GL_TEXTURE_RED_SIZE:
    case GL_TEXTURE_GREEN_SIZE:
    case GL_TEXTURE_BLUE_SIZE:
    case GL_TEXTURE_ALPHA_SIZE:
    case GL_TEXTURE_LUMINANCE_SIZE:
    case GL_TEXTURE_INTENSITY_SIZE: a.values = {defined ? componentBits(l, name) : 0.0}; break;
    default: return setError(*s, GL_INVALID_ENUM);
    }
    if (out) answer(a, out);
}

template <class T>
void getTexEnv(GLenum target, GLenum name, T* out) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || !out) return;
    if (target != GL_TEXTURE_ENV) return setError(*s, GL_INVALID_ENUM);
    const TextureUnit& unit = s->textures;
    if (name == GL_TEXTURE_ENV_MODE) return answer(Answer{{double(unit.envMode)}}, out);
    if (name == GL_TEXTURE_ENV_COLOR) {
        return answer(Answer{{unit.envColor.r, unit.envColor.g, unit.envColor.b, unit.envColor.a}, true}, out);
    }
    setError(*s, GL_INVALID_ENUM);
}

void getTexImage(GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (!isTextureTarget(target)) return setError(*s, GL_INVALID_ENUM);
    if (level < 0 || level >= kMaxTextureLevels) return setError(*s, GL_INVALID_VALUE);
    if (!isPixelFormat(format) || !isPixelType(type) || type == GL_BITMAP) return setError(*s, GL_INVALID_ENUM);
    if (format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT) {
        return setError(*s, GL_INVALID_OPERATION);
    }
    const TextureLevel& l = boundTexture(s->textures, target).levels[static_cast<std::size_t>(level)];
    if (!l.defined || !pixels) return;
    packTexels(l.texels, l.imageWidth, l.imageHeight, l.base, format, type, s->pack, pixels);
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glTexParameterf, +[](GLenum target, GLenum name, GLfloat v) { texParameter(target, name, &v, 1); }>(),
    listed<gl::glTexParameteri, +[](GLenum target, GLenum name, GLint v) { texParameteri(target, name, &v, 1); }>(),
    listed<gl::glTexParameterfv,
           +[](GLenum target, GLenum name, const GLfloat* v) {
               texParameter(target, name, v, static_cast<int>(glcalls::texParameterCount(target, name, v)));
           }>(),
    listed<gl::glTexParameteriv,
           +[](GLenum target, GLenum name, const GLint* v) {
               texParameteri(target, name, v, static_cast<int>(glcalls::texParameterCount(target, name, v)));
           }>(),
    listed<gl::glTexEnvf, +[](GLenum target, GLenum name, GLfloat v) { texEnv(target, name, &v, 1); }>(),
    listed<gl::glTexEnvi, +[](GLenum target, GLenum name, GLint v) { texEnvi(target, name, &v, 1); }>(),
    listed<gl::glTexEnvfv,
           +[](GLenum target, GLenum name, const GLfloat* v) {
               texEnv(target, name, v, static_cast<int>(glcalls::texEnvCount(target, name, v)));
           }>(),
    listed<gl::glTexEnviv,
           +[](GLenum target, GLenum name, const GLint* v) {
               texEnvi(target, name, v, static_cast<int>(glcalls::texEnvCount(target, name, v)));
           }>(),
    listed<gl::glGetTexParameterfv,
           +[](GLenum target, GLenum name, GLfloat* out) { getTexParameter(target, name, out); }>(),
    listed<gl::glGetTexParameteriv,
           +[](GLenum target, GLenum name, GLint* out) { getTexParameter(target, name, out); }>(),
    listed<gl::glGetTexLevelParameterfv, +[](GLenum target, GLint level, GLenum name,
                                             GLfloat* out) { getTexLevelParameter(target, level, name, out); }>(),
    listed<gl::glGetTexLevelParameteriv, +[](GLenum target, GLint level, GLenum name,
                                             GLint* out) { getTexLevelParameter(target, level, name, out); }>(),
    listed<gl::glGetTexEnvfv, +[](GLenum target, GLenum name, GLfloat* out) { getTexEnv(target, name, out); }>(),
    listed<gl::glGetTexEnviv, +[](GLenum target, GLenum name, GLint* out) { getTexEnv(target, name, out); }>(),
    listed<gl::glGetTexImage, +[](GLenum target, GLint level, GLenum format, GLenum type,
                                  void* pixels) { getTexImage(target, level, format, type, pixels); }>(),
};

glrenderer::TextureWrap wrapOf(GLenum wrap, bool blends) {
    if (wrap == GL_REPEAT) return glrenderer::TextureWrap::Repeat;
    return wrap == GL_CLAMP && blends ? glrenderer::TextureWrap::Clamp : glrenderer::TextureWrap::ClampToEdge;
}

// A colour as a texture of base format `base` holds it (Mesa's st_translate_color): what the
// border colour becomes.
glm::vec4 asBaseFormat(const glm::vec4& c, glrenderer::TextureBase base) {
    using glrenderer::TextureBase;
    switch (base) {
    case TextureBase::Alpha: return {0.0f, 0.0f, 0.0f, c.a};
    case TextureBase::Luminance: return {c.r, c.r, c.r, 1.0f};
    case TextureBase::LuminanceAlpha: return {c.r, c.r, c.r, c.a};
    case TextureBase::Intensity: return {c.r, c.r, c.r, c.r};
    case TextureBase::Rgb: return {c.r, c.g, c.b, 1.0f};
    case TextureBase::Rgba: break;
    }
    return c;
}

}  // namespace

void updateTexturing(Context::State& s) {
    TextureUnit& unit = s.textures;
    glrenderer::TextureState next;
    TextureObject* t = unit.enabled2D   ? &boundTexture(unit, GL_TEXTURE_2D)
                       : unit.enabled1D ? &boundTexture(unit, GL_TEXTURE_1D)
                                        : nullptr;
    const std::size_t levels = t ? sampledLevels(*t) : 0;
    if (levels > 0) {
        if (!t->snapshot || t->snapshot->levelCount != static_cast<int>(levels)) {
            t->snapshot = textureSnapshot(std::span<const TextureLevel>(t->levels.data(), levels));
        }
        using glrenderer::MipmapFilter;
        using glrenderer::TextureFilter;
        const GLenum min = t->minFilter;
        next.env = envOf(unit.envMode);
        next.oneDimensional = !unit.enabled2D;
        next.base = t->levels[0].base;
        next.minFilter = min == GL_NEAREST || min == GL_NEAREST_MIPMAP_NEAREST || min == GL_NEAREST_MIPMAP_LINEAR
                             ? TextureFilter::Nearest
                             : TextureFilter::Linear;
        next.magFilter = t->magFilter == GL_LINEAR ? TextureFilter::Linear : TextureFilter::Nearest;
        next.mipFilter = !isMipmapFilter(min)                                                  ? MipmapFilter::None
                         : min == GL_NEAREST_MIPMAP_NEAREST || min == GL_LINEAR_MIPMAP_NEAREST ? MipmapFilter::Nearest
                                                                                               : MipmapFilter::Linear;
        // GL_CLAMP samples as GL_CLAMP_TO_EDGE when no filter reaches past a texel (the
        // reference's float sampler gives the same bits then); a 1D texture has no T.
        const bool blends = next.minFilter == TextureFilter::Linear || next.magFilter == TextureFilter::Linear ||
                            next.mipFilter == MipmapFilter::Linear;
        next.wrapS = wrapOf(t->wrapS, blends);
        next.wrapT = next.oneDimensional ? glrenderer::TextureWrap::Repeat : wrapOf(t->wrapT, blends);
        if (next.wrapS == glrenderer::TextureWrap::Clamp || next.wrapT == glrenderer::TextureWrap::Clamp) {
            next.borderColor = asBaseFormat(t->borderColor, next.base);
        }
        next.envColor = unit.envColor;
        next.gen = unit.gen;
        const bool sphere = ((unit.gen.enabled & 1u) && unit.genMode[0] == GL_SPHERE_MAP) ||
                            ((unit.gen.enabled & 2u) && unit.genMode[1] == GL_SPHERE_MAP);
        if (sphere) {  // SPHERE_MAP's eye normals
            s.modelview.top().settleKind();
            next.gen.inverseModelview = s.modelview.top().inverse();
            next.gen.normalize = s.lighting.normalize;
        }
        next.matrix = s.texture.top().matrix();
        next.identityMatrix = next.matrix == kIdentity;
        next.texture = t->snapshot;
    }
    if (!(next == s.draw->texture)) s.draw.edit().texture = std::move(next);
}

bool setTextureCapability(Context::State& s, GLenum cap, bool enabled) {
    if (cap != GL_TEXTURE_1D && cap != GL_TEXTURE_2D) return false;
    bool& flag = cap == GL_TEXTURE_1D ? s.textures.enabled1D : s.textures.enabled2D;
    if (flag != enabled) endBatch(s);
    flag = enabled;
    return true;
}

std::optional<bool> textureCapability(const Context::State& s, GLenum cap) {
    if (cap == GL_TEXTURE_1D) return s.textures.enabled1D;
    if (cap == GL_TEXTURE_2D) return s.textures.enabled2D;
    return std::nullopt;
}

std::optional<std::vector<double>> textureQuery(const Context::State& s, GLenum name) {
    switch (name) {
    case GL_TEXTURE_BINDING_1D: return std::vector<double>{double(s.textures.bound1D)};
    case GL_TEXTURE_BINDING_2D: return std::vector<double>{double(s.textures.bound2D)};
    case GL_MAX_TEXTURE_SIZE: return std::vector<double>{double(kMaxTextureSize)};
    default: return std::nullopt;
    }
}

std::span<const EntryPoint> textureParameterEntryPoints() { return kEntryPoints; }

}  // namespace mygl
