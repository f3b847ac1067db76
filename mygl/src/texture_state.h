#pragma once
// Texture objects and the texture unit's state on the GL side (textures.cpp); the pipeline's
// TextureState is formed from them before each draw (updateTexturing).
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <glad/gl.h>

#include <mygl/gl12_enums.h>

#include <glm/vec4.hpp>
#include <glrenderer/texture.h>

namespace mygl {

// The reference's largest texture (llvmpipe: 2^14 texels a side), and so its levels.
inline constexpr int kMaxTextureLevels = 15;
inline constexpr int kMaxTextureSize = 1 << (kMaxTextureLevels - 1);

// One mipmap level: its size as given, its internal format and its image (border stripped,
// as the reference stores it), in RGBA8 texels (glrenderer::Texture).
struct TextureLevel {
    int width = 0, height = 0, border = 0;
    GLint internalFormat = 1;
    glrenderer::TextureBase base = glrenderer::TextureBase::Rgba;
    bool defined = false;
    int imageWidth = 0, imageHeight = 0;
    std::vector<std::uint32_t> texels;
};

struct TextureObject {
    explicit TextureObject(GLenum boundTarget = 0) : target(boundTarget) {}

    GLenum target;  // GL_TEXTURE_1D or GL_TEXTURE_2D once bound (a proxy target for proxies)
    std::array<TextureLevel, kMaxTextureLevels> levels;
    GLenum minFilter = GL_NEAREST_MIPMAP_LINEAR, magFilter = GL_LINEAR;
    GLenum wrapS = GL_REPEAT, wrapT = GL_REPEAT;
    glm::vec4 borderColor{0.0f};
    float priority = 1.0f;
    // The images as the pipeline samples them, made again after any of them changes (null
    // then): queued batches keep the one they read.
    std::shared_ptr<const glrenderer::Texture> snapshot;
};

// GL's initial planes: S takes x, T takes y, R and Q nothing.
inline glrenderer::TextureGen defaultTextureGen() {
    glrenderer::TextureGen gen;
    gen.objectPlane[0] = gen.eyePlane[0] = {1, 0, 0, 0};
    gen.objectPlane[1] = gen.eyePlane[1] = {0, 1, 0, 0};
    return gen;
}

// The one texture unit of GL 1.1.
struct TextureUnit {
    std::map<GLuint, TextureObject> objects;  // the named ones; name 0 is each target's default
    GLuint largestNameEver = 0;               // deleting does not lower it (Mesa's hash table MaxKey)
    TextureObject default1D{GL_TEXTURE_1D}, default2D{GL_TEXTURE_2D};
    GLuint bound1D = 0, bound2D = 0;
    bool enabled1D = false, enabled2D = false;
    GLenum envMode = GL_MODULATE;
    glm::vec4 envColor{0.0f};
    // glTexGen per coordinate S, T, R, Q: the pipeline's planes and enables, and the modes as
    // GL names them.
    glrenderer::TextureGen gen = defaultTextureGen();
    std::array<GLenum, 4> genMode{GL_EYE_LINEAR, GL_EYE_LINEAR, GL_EYE_LINEAR, GL_EYE_LINEAR};
    // Proxy textures keep only their levels' sizes and formats.
    TextureObject proxy1D{GL_PROXY_TEXTURE_1D}, proxy2D{GL_PROXY_TEXTURE_2D};
};

}  // namespace mygl
