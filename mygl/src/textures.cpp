// Texture objects and their images: glGenTextures, glBindTexture, glDeleteTextures,
// glIsTexture, glAreTexturesResident, glPrioritizeTextures, glTexImage1D/2D, glTexSubImage1D/2D,
// glCopyTexImage1D/2D, glCopyTexSubImage1D/2D.
#include <algorithm>
#include <bit>
#include <cstring>

#include "compiled.h"
#include "texture_images.h"
#include "textures.h"

namespace mygl {
namespace {

bool isTarget(GLenum target, int dims) {
    return dims == 1 ? target == GL_TEXTURE_1D || target == GL_PROXY_TEXTURE_1D
                     : target == GL_TEXTURE_2D || target == GL_PROXY_TEXTURE_2D;
}
bool isProxy(GLenum target) { return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D; }

// The format and type as GL names them (GL_BITMAP only for index images).
GLenum pixelEnumsError(GLenum format, GLenum type) {
    if (!isPixelFormat(format) || !isPixelType(type)) return GL_INVALID_ENUM;
    if (type == GL_BITMAP && format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX) return GL_INVALID_ENUM;
    return GL_NO_ERROR;
}
// Stencil and depth images have no place in a colour texture.
GLenum colorFormatError(GLenum format) {
    return format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT ? GL_INVALID_OPERATION : GL_NO_ERROR;
}

// A colour or colour-index image for glTexImage or glTexSubImage.
GLenum pixelFormatError(GLenum format, GLenum type) {
    if (const GLenum error = pixelEnumsError(format, type)) return error;
    return colorFormatError(format);
}

// The image's colours after the pixel transfer as it is now.
std::vector<glm::vec4> transferred(const Context::State& s, const UnpackedImage& image) {
    return transferredImage(image, s.pixelModes, s.pixelMaps);
}

// The level's image from unpacked colours (border stripped).
void defineLevel(TextureLevel& level, int width, int height, int border, GLint internalFormat,
                 const std::vector<glm::vec4>& rgba) {
    const glrenderer::TextureBase base = *textureBaseOf(internalFormat);
    level.width = width, level.height = height, level.border = border;
    level.internalFormat = internalFormat;
    level.base = base;
    level.defined = true;
    level.imageWidth = width - 2 * border;
    // A 1D texture (height 1) has one row, its border or not; a 2D one with height 2 * border none.
    level.imageHeight = height == 1 ? 1 : height - 2 * border;
    std::vector<glm::vec4> inner;
    if (border == 0) {
        inner = rgba;
    } else {
        inner.reserve(static_cast<std::size_t>(level.imageWidth) * static_cast<std::size_t>(level.imageHeight));
        for (int y = height > 1 ? border : 0; y < (height > 1 ? height - border : 1); ++y) {
            for (int x = border; x < width - border; ++x)
                inner.push_back(rgba[static_cast<std::size_t>(y * width + x)]);
        }
    }
    level.texels = textureTexels(inner, base);
}

// The checks of glTexImage before the data is read; GL_NO_ERROR when the call may proceed.
GLenum texImageError(GLenum target, int dims, GLint level, GLint internalFormat, GLsizei width, GLsizei height,
                     GLint border, GLenum format, GLenum type) {
    // In the reference's order (a call with several errors records the first).
    if (!isTarget(target, dims)) return GL_INVALID_ENUM;
    if (level < 0 || level >= kMaxTextureLevels) return GL_INVALID_VALUE;
    if (border != 0 && border != 1) return GL_INVALID_VALUE;
    if (width < 0 || height < 0) return GL_INVALID_VALUE;
    if (const GLenum error = pixelEnumsError(format, type)) return error;
    if (!textureBaseOf(internalFormat)) return GL_INVALID_VALUE;
    if (const GLenum error = colorFormatError(format)) return error;
    const int limit = (kMaxTextureSize >> level) + 2 * border;
    if (width < 2 * border || width > limit) return GL_INVALID_VALUE;
    if (dims == 2 && (height < 2 * border || height > limit)) return GL_INVALID_VALUE;
    return GL_NO_ERROR;
}

void texImage(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height, GLint border,
              const std::vector<glm::vec4>& rgba) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    TextureObject& texture = boundTexture(s->textures, target);
    TextureLevel& defined = texture.levels[static_cast<std::size_t>(level)];
    if (isProxy(target)) {
        defined.width = width, defined.height = height, defined.border = border;
        defined.internalFormat = internalFormat;
        return;
    }
    defineLevel(defined, width, height, border, internalFormat, rgba);
    texture.snapshot.reset();
}

// glTexImage1D/2D: checks, then the pixels unpacked now (as the reference does when it compiles
// the call into a list); the pixel transfer when the call runs.
void texImageCall(GLenum target, int dims, GLint level, GLint internalFormat, GLsizei width, GLsizei height,
                  GLint border, GLenum format, GLenum type, const void* pixels) {
    Context::State* s = currentState();
    if (!s) return;
    if (!s->lists.compiling() && s->insideBeginEnd) return setError(*s, GL_INVALID_OPERATION);
    const GLenum error = texImageError(target, dims, level, internalFormat, width, height, border, format, type);
    UnpackedImage image;
    if (error == GL_NO_ERROR && !isProxy(target))
        image = unpackTextureImage(pixels, width, height, format, type, s->unpack,
                                   s->lists.compiling() || s->pixelModes.transfersColor());
    auto call = [=, image = std::move(image)] {
        Context::State* now = stateOutsideBeginEnd();
        if (!now) return;
        if (error != GL_NO_ERROR) return setError(*now, error);
        texImage(target, level, internalFormat, width, height, border, transferred(*now, image));
    };
    if (s->lists.compiling()) {
        s->lists.add(call);
        if (!s->lists.executingWhileCompiling()) return;
    }
    call();
}

// glTexSubImage's rectangle [x, x + width) x [y, y + height) of level `level`, in the level's
// coordinates with its border; the checks first, then the new image.
void texSubImage(GLenum target, int dims, GLint level, GLint x, GLint y, GLsizei width, GLsizei height,
                 const std::vector<glm::vec4>& rgba) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    TextureObject& texture = boundTexture(s->textures, target);
    TextureLevel& defined = texture.levels[static_cast<std::size_t>(level)];
    const int b = defined.border;
    if (x < -b || y < -b || x + width > defined.width - b || (dims == 2 && y + height > defined.height - b)) {
        return setError(*s, GL_INVALID_VALUE);
    }
    if (width == 0 || height == 0) return;
    // The border is not stored: only the rectangle's part inside the image is written.
    std::vector<glm::vec4> inner;
    const int x0 = std::max(x, 0), y0 = std::max(y, 0);
    const int x1 = std::min(x + width, defined.imageWidth), y1 = std::min(y + height, defined.imageHeight);
    if (x0 >= x1 || y0 >= y1) return;
    for (int row = y0; row < y1; ++row) {
        for (int column = x0; column < x1; ++column)
            inner.push_back(rgba[static_cast<std::size_t>((row - y) * width + column - x)]);
    }
    endBatch(*s);  // the reference draws its pending vertices and forgets their format
    writeSubImage(defined, x0, y0, x1 - x0, y1 - y0, inner);
    texture.snapshot.reset();  // batches queued with the old images keep them
}

// In the reference's order: a negative size before an undefined level.
GLenum texSubImageError(Context::State& s, GLenum target, int dims, GLint level, GLsizei width, GLsizei height,
                        GLenum format, GLenum type) {
    if (!isTarget(target, dims) || isProxy(target)) return GL_INVALID_ENUM;
    if (level < 0 || level >= kMaxTextureLevels) return GL_INVALID_VALUE;
    if (width < 0 || height < 0) return GL_INVALID_VALUE;
    if (!boundTexture(s.textures, target).levels[static_cast<std::size_t>(level)].defined) return GL_INVALID_OPERATION;
    return pixelFormatError(format, type);
}

void texSubImageCall(GLenum target, int dims, GLint level, GLint x, GLint y, GLsizei width, GLsizei height,
                     GLenum format, GLenum type, const void* pixels) {
    Context::State* s = currentState();
    if (!s) return;
    const bool compiling = s->lists.compiling();
    if (!compiling && s->insideBeginEnd) return setError(*s, GL_INVALID_OPERATION);
    GLenum error = compiling ? GL_NO_ERROR : texSubImageError(*s, target, dims, level, width, height, format, type);
    UnpackedImage image;
    if (error == GL_NO_ERROR && isPixelFormat(format) && isPixelType(type) && width > 0 && height > 0) {
        image = unpackTextureImage(pixels, width, height, format, type, s->unpack,
                                   compiling || s->pixelModes.transfersColor());
    }
    auto call = [=, image = std::move(image)] {
        Context::State* now = stateOutsideBeginEnd();
        if (!now) return;
        const GLenum found = texSubImageError(*now, target, dims, level, width, height, format, type);
        if (found != GL_NO_ERROR) return setError(*now, found);
        texSubImage(target, dims, level, x, y, width, height, transferred(*now, image));
    };
    if (compiling) {
        s->lists.add(call);
        if (!s->lists.executingWhileCompiling()) return;
    }
    call();
}

// The framebuffer's colours in [x, x + width) x [y, y + height) (window coordinates), black
// outside the window, as RGBA.
std::vector<glm::vec4> readFramebuffer(Context::State& s, GLint x, GLint y, GLsizei width, GLsizei height) {
    drawCachedBitmaps(s);
    s.pipeline.finish();
    const auto& fb = s.framebuffer;
    std::vector<glm::vec4> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), glm::vec4(0.0f));
    for (int row = 0; row < height; ++row) {
        for (int column = 0; column < width; ++column) {
            const std::int64_t fx = std::int64_t{x} + column, fy = std::int64_t{y} + row;
            if (fx < 0 || fy < 0 || fx >= fb.width() || fy >= fb.height()) continue;
            const std::uint32_t word = fb.color()[static_cast<std::size_t>(fy * fb.width() + fx)];
            glm::vec4& c = rgba[static_cast<std::size_t>(row * width + column)];
            // Times 1/255 as the reference reads the framebuffer into floats under a pixel transfer.
            for (int i = 0; i < 4; ++i) c[i] = static_cast<float>((word >> (8 * i)) & 0xFFu) * (1.0f / 255.0f);
        }
    }
    return rgba;
}

void copyTexImage(GLenum target, int dims, GLint level, GLenum internalFormat, GLint x, GLint y, GLsizei width,
                  GLsizei height, GLint border) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (isProxy(target)) return setError(*s, GL_INVALID_ENUM);
    const GLenum error = texImageError(target, dims, level, static_cast<GLint>(internalFormat), width, height, border,
                                       GL_RGBA, GL_FLOAT);
    if (error != GL_NO_ERROR) return setError(*s, error);
    // 1, 2, 3 and 4 are not internal formats here.
    if (internalFormat >= 1 && internalFormat <= 4) return setError(*s, GL_INVALID_VALUE);
    texImage(target, level, static_cast<GLint>(internalFormat), width, height, border,
             transferred(*s, UnpackedImage{readFramebuffer(*s, x, y, width, height), {}, {}, 0, true}));
}

void copyTexSubImage(GLenum target, int dims, GLint level, GLint xOffset, GLint yOffset, GLint x, GLint y,
                     GLsizei width, GLsizei height) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    // The reference checks the level here before the size.
    const GLenum error = texSubImageError(*s, target, dims, level, 0, 0, GL_RGBA, GL_FLOAT);
    if (error != GL_NO_ERROR) return setError(*s, error);
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    texSubImage(target, dims, level, xOffset, yOffset, width, height,
                transferred(*s, UnpackedImage{readFramebuffer(*s, x, y, width, height), {}, {}, 0, true}));
}

void genTextures(GLsizei n, GLuint* names) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (n < 0) return setError(*s, GL_INVALID_VALUE);
    if (!names) return;
    auto& objects = s->textures.objects;
    // Consecutive names after the largest ever given or bound, deleted or not, as the reference
    // gives them (_mesa_HashFindFreeKeyBlock); after the largest in use when those would overflow.
    GLuint& largest = s->textures.largestNameEver;
    GLuint next = largest < 0xFFFFFFFEu - static_cast<GLuint>(n) ? largest + 1
                                                                 : (objects.empty() ? 1 : objects.rbegin()->first + 1);
    for (GLsizei i = 0; i < n; ++i) {
        objects.emplace(next, TextureObject{});
        names[i] = next++;
    }
    largest = std::max(largest, next - 1);
}

void bindTexture(GLenum target, GLuint name) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D) return setError(*s, GL_INVALID_ENUM);
    if (name != 0) {
        s->textures.largestNameEver = std::max(s->textures.largestNameEver, name);
        TextureObject& texture = s->textures.objects[name];
        if (texture.target != 0 && texture.target != target) return setError(*s, GL_INVALID_OPERATION);
        texture.target = target;
    }
    (target == GL_TEXTURE_1D ? s->textures.bound1D : s->textures.bound2D) = name;
}

void deleteTextures(GLsizei n, const GLuint* names) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (n < 0) return setError(*s, GL_INVALID_VALUE);
    if (!names) return;
    TextureUnit& unit = s->textures;
    for (GLsizei i = 0; i < n; ++i) {
        if (names[i] == 0) continue;
        if (unit.bound1D == names[i]) unit.bound1D = 0;
        if (unit.bound2D == names[i]) unit.bound2D = 0;
        unit.objects.erase(names[i]);
    }
}

GLboolean isTexture(GLuint name) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || name == 0) return GL_FALSE;
    const auto found = s->textures.objects.find(name);
    return found != s->textures.objects.end() && found->second.target != 0 ? GL_TRUE : GL_FALSE;
}

// Every texture is resident: the reference answers GL_TRUE and leaves `residences` unwritten.
GLboolean areTexturesResident(GLsizei n, const GLuint* names, GLboolean*) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return GL_FALSE;
    if (n < 0) return setError(*s, GL_INVALID_VALUE), GL_FALSE;
    for (GLsizei i = 0; names && i < n; ++i) {
        const auto found = s->textures.objects.find(names[i]);
        if (names[i] == 0 || found == s->textures.objects.end() || found->second.target == 0) {
            return setError(*s, GL_INVALID_VALUE), GL_FALSE;
        }
    }
    return GL_TRUE;
}

void prioritizeTextures(GLsizei n, const GLuint* names, const GLclampf* priorities) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (n < 0) return setError(*s, GL_INVALID_VALUE);
    if (!names || !priorities) return;
    for (GLsizei i = 0; i < n; ++i) {
        const auto found = s->textures.objects.find(names[i]);
        if (names[i] != 0 && found != s->textures.objects.end()) {
            found->second.priority = std::clamp(priorities[i], 0.0f, 1.0f);
        }
    }
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glGenTextures, +[](GLsizei n, GLuint* names) { genTextures(n, names); }>(),
    listed<gl::glBindTexture, +[](GLenum target, GLuint name) { bindTexture(target, name); }>(),
    listed<gl::glDeleteTextures, +[](GLsizei n, const GLuint* names) { deleteTextures(n, names); }>(),
    listed<gl::glIsTexture, +[](GLuint name) { return isTexture(name); }>(),
    listed<gl::glAreTexturesResident,
           +[](GLsizei n, const GLuint* names, GLboolean* residences) {
               return areTexturesResident(n, names, residences);
           }>(),
    listed<gl::glPrioritizeTextures, +[](GLsizei n, const GLuint* names,
                                         const GLclampf* priorities) { prioritizeTextures(n, names, priorities); }>(),
    listed<gl::glTexImage1D,
           +[](GLenum target, GLint level, GLint internalFormat, GLsizei width, GLint border, GLenum format,
               GLenum type, const void* pixels) {
               texImageCall(target, 1, level, internalFormat, width, 1, border, format, type, pixels);
           }>(),
    listed<gl::glTexImage2D,
           +[](GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height, GLint border,
               GLenum format, GLenum type, const void* pixels) {
               texImageCall(target, 2, level, internalFormat, width, height, border, format, type, pixels);
           }>(),
    listed<gl::glTexSubImage1D,
           +[](GLenum target, GLint level, GLint x, GLsizei width, GLenum format, GLenum type, const void* pixels) {
               texSubImageCall(target, 1, level, x, 0, width, 1, format, type, pixels);
           }>(),
    listed<gl::glTexSubImage2D,
           +[](GLenum target, GLint level, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
               const void* pixels) { texSubImageCall(target, 2, level, x, y, width, height, format, type, pixels); }>(),
    listed<gl::glCopyTexImage1D,
           +[](GLenum target, GLint level, GLenum internalFormat, GLint x, GLint y, GLsizei width, GLint border) {
               copyTexImage(target, 1, level, internalFormat, x, y, width, 1, border);
           }>(),
    listed<gl::glCopyTexImage2D,
           +[](GLenum target, GLint level, GLenum internalFormat, GLint x, GLint y, GLsizei width, GLsizei height,
               GLint border) { copyTexImage(target, 2, level, internalFormat, x, y, width, height, border); }>(),
    listed<gl::glCopyTexSubImage1D,
           +[](GLenum target, GLint level, GLint xOffset, GLint x, GLint y, GLsizei width) {
               copyTexSubImage(target, 1, level, xOffset, 0, x, y, width, 1);
           }>(),
    listed<gl::glCopyTexSubImage2D,
           +[](GLenum target, GLint level, GLint xOffset, GLint yOffset, GLint x, GLint y, GLsizei width,
               GLsizei height) { copyTexSubImage(target, 2, level, xOffset, yOffset, x, y, width, height); }>(),
};

}  // namespace

namespace {

// The object of `target` in `unit` (const or not); a bound name always has its object.
template <class Unit>
auto& boundIn(Unit& unit, GLenum target) {
    switch (target) {
    case GL_TEXTURE_1D: return unit.bound1D ? unit.objects.at(unit.bound1D) : unit.default1D;
    case GL_PROXY_TEXTURE_1D: return unit.proxy1D;
    case GL_PROXY_TEXTURE_2D: return unit.proxy2D;
    default: return unit.bound2D ? unit.objects.at(unit.bound2D) : unit.default2D;
    }
}

}  // namespace

TextureObject& boundTexture(TextureUnit& unit, GLenum target) { return boundIn(unit, target); }
const TextureObject& boundTexture(const TextureUnit& unit, GLenum target) { return boundIn(unit, target); }

std::span<const EntryPoint> textureEntryPoints() { return kEntryPoints; }

}  // namespace mygl
