#pragma once
// Count rules: how many elements a GL call's pointer argument points at, as a function of the
// call's arguments (and, for client images, of the unpack modes in force). gl11_calls.h names one
// per call; MyGL's display lists and the reference's CallRecorder copy that many elements.
// A rule never reads the data, and gives a count the call's arguments allow even when the call
// is an error (GL reads nothing then: copying less is harmless, copying more could read past
// the program's array).
#include <glad/gl.h>

#include <algorithm>
#include <cstddef>

namespace glcalls {

inline std::size_t nonNegative(GLsizei n) { return n > 0 ? static_cast<std::size_t>(n) : 0; }

// glLight*v: 4 for colours and the position, 3 for the spot direction, 1 otherwise.
template <class T>
std::size_t lightCount(GLenum, GLenum name, const T*) {
    return name == GL_AMBIENT || name == GL_DIFFUSE || name == GL_SPECULAR || name == GL_POSITION ? 4
           : name == GL_SPOT_DIRECTION                                                            ? 3
                                                                                                  : 1;
}
// glMaterial*v: 4 for colours, 3 colour indexes, 1 otherwise (the shininess).
template <class T>
std::size_t materialCount(GLenum, GLenum name, const T*) {
    return name == GL_AMBIENT || name == GL_DIFFUSE || name == GL_SPECULAR || name == GL_EMISSION ||
                   name == GL_AMBIENT_AND_DIFFUSE
               ? 4
           : name == GL_COLOR_INDEXES ? 3
                                      : 1;
}
template <class T>
std::size_t lightModelCount(GLenum name, const T*) {
    return name == GL_LIGHT_MODEL_AMBIENT ? 4 : 1;
}
template <class T>
std::size_t fogCount(GLenum name, const T*) {
    return name == GL_FOG_COLOR ? 4 : 1;
}
template <class T>
std::size_t texParameterCount(GLenum, GLenum name, const T*) {
    return name == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
}
template <class T>
std::size_t texEnvCount(GLenum, GLenum name, const T*) {
    return name == GL_TEXTURE_ENV_COLOR ? 4 : 1;
}
template <class T>
std::size_t texGenCount(GLenum, GLenum name, const T*) {
    return name == GL_OBJECT_PLANE || name == GL_EYE_PLANE ? 4 : 1;
}

// glMap1/glMap2: the last control point's offset plus its components; 1 for arguments the call
// rejects, so that a kept call still passes a pointer and fails as the call did.
inline std::size_t mapCount(GLenum target, GLenum first, GLint ustride, GLint uorder, GLint vstride, GLint vorder) {
    constexpr GLint kComponents[] = {4, 1, 3, 1, 2, 3, 4, 3, 4};  // COLOR_4, INDEX, NORMAL, TEXTURE_COORD_1..4,
                                                                  // VERTEX_3, VERTEX_4
    constexpr GLint kMaxOrder = 30;
    if (target < first || target > first + 8) return 1;
    const GLint size = kComponents[target - first];
    if (uorder < 1 || uorder > kMaxOrder || vorder < 1 || vorder > kMaxOrder || ustride < size || vstride < size)
        return 1;
    return std::size_t(uorder - 1) * std::size_t(ustride) + std::size_t(vorder - 1) * std::size_t(vstride) +
           std::size_t(size);
}
template <class T>
std::size_t map1Count(GLenum target, T, T, GLint stride, GLint order, const T*) {
    return mapCount(target, GL_MAP1_COLOR_4, stride, order, stride, 1);
}
template <class T>
std::size_t map2Count(GLenum target, T, T, GLint ustride, GLint uorder, T, T, GLint vstride, GLint vorder, const T*) {
    return mapCount(target, GL_MAP2_COLOR_4, ustride, uorder, vstride, vorder);
}

// glPixelMap: `size` entries.
template <class T>
std::size_t pixelMapCount(GLenum, GLsizei size, const T*) {
    return nonNegative(size);
}
// Arrays of n texture names (and priorities).
inline std::size_t namesCount(GLsizei n, const GLuint*) { return nonNegative(n); }
inline std::size_t generatedCount(GLsizei n, GLuint*) { return nonNegative(n); }
inline std::size_t priorityCount(GLsizei n, const GLuint*, const GLclampf*) { return nonNegative(n); }

// Bytes of n list names or indices of `type` (glCallLists, glDrawElements).
inline std::size_t bytesOf(GLenum type, GLsizei n) {
    const std::size_t count = nonNegative(n);
    switch (type) {
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_2_BYTES: return 2 * count;
    case GL_3_BYTES: return 3 * count;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT:
    case GL_4_BYTES: return 4 * count;
    default: return count;
    }
}
inline std::size_t callListsBytes(GLsizei n, GLenum type, const void*) { return bytesOf(type, n); }
inline std::size_t elementBytes(GLenum, GLsizei count, GLenum type, const void*) { return bytesOf(type, count); }

// The unpack modes (glPixelStore) a client image is read with.
struct UnpackModes {
    GLint alignment = 4;
    GLint rowLength = 0;
    GLint skipPixels = 0;
    GLint skipRows = 0;
};

// Bytes of a client image of width x height pixels under `unpack`, up to the last byte read.
inline std::size_t imageBytes(const UnpackModes& unpack, GLsizei width, GLsizei height, GLenum format, GLenum type) {
    if (width <= 0 || height <= 0) return 0;
    const std::size_t components = format == GL_RGBA || format == 0x80E1 /* GL_BGRA */ ? 4
                                   : format == GL_RGB || format == 0x80E0 /* GL_BGR */ ? 3
                                   : format == GL_LUMINANCE_ALPHA                      ? 2
                                                                                       : 1;
    const std::size_t component = type == GL_UNSIGNED_BYTE || type == GL_BYTE     ? 1
                                  : type == GL_UNSIGNED_SHORT || type == GL_SHORT ? 2
                                                                                  : 4;
    const std::size_t pixel = components * component;
    const std::size_t rowPixels = static_cast<std::size_t>(unpack.rowLength > 0 ? unpack.rowLength : width);
    const std::size_t a = unpack.alignment > 0 ? static_cast<std::size_t>(unpack.alignment) : 1;
    const std::size_t skipRows = static_cast<std::size_t>(std::max(unpack.skipRows, 0));
    const std::size_t skipPixels = static_cast<std::size_t>(std::max(unpack.skipPixels, 0));
    if (type == GL_BITMAP) {  // rows of bits padded to the alignment; skipped pixels are bits
        const std::size_t rowBytes = (rowPixels + 8 * a - 1) / (8 * a) * a;
        return skipRows * rowBytes + skipPixels / 8 + static_cast<std::size_t>(height - 1) * rowBytes +
               (skipPixels % 8 + static_cast<std::size_t>(width) + 7) / 8;
    }
    std::size_t stride = rowPixels * pixel;
    if (component < a) stride = (stride + a - 1) / a * a;
    return skipRows * stride + skipPixels * pixel + static_cast<std::size_t>(height - 1) * stride +
           static_cast<std::size_t>(width) * pixel;
}
inline std::size_t bitmapBytes(const UnpackModes& unpack, GLsizei w, GLsizei h, GLfloat, GLfloat, GLfloat, GLfloat,
                               const GLubyte*) {
    return imageBytes(unpack, w, h, GL_COLOR_INDEX, GL_BITMAP);
}
// glPolygonStipple: 32 x 32 bits.
inline std::size_t polygonStippleBytes(const UnpackModes& unpack, const GLubyte*) {
    return imageBytes(unpack, 32, 32, GL_COLOR_INDEX, GL_BITMAP);
}
inline std::size_t drawPixelsBytes(const UnpackModes& unpack, GLsizei w, GLsizei h, GLenum format, GLenum type,
                                   const void*) {
    return imageBytes(unpack, w, h, format, type);
}
inline std::size_t texImage1DBytes(const UnpackModes& unpack, GLenum, GLint, GLint, GLsizei w, GLint, GLenum format,
                                   GLenum type, const void*) {
    return imageBytes(unpack, w, 1, format, type);
}
inline std::size_t texImage2DBytes(const UnpackModes& unpack, GLenum, GLint, GLint, GLsizei w, GLsizei h, GLint,
                                   GLenum format, GLenum type, const void*) {
    return imageBytes(unpack, w, h, format, type);
}
inline std::size_t texSubImage1DBytes(const UnpackModes& unpack, GLenum, GLint, GLint, GLsizei w, GLenum format,
                                      GLenum type, const void*) {
    return imageBytes(unpack, w, 1, format, type);
}
inline std::size_t texSubImage2DBytes(const UnpackModes& unpack, GLenum, GLint, GLint, GLint, GLsizei w, GLsizei h,
                                      GLenum format, GLenum type, const void*) {
    return imageBytes(unpack, w, h, format, type);
}

}  // namespace glcalls
