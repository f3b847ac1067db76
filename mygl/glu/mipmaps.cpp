// gluScaleImage and gluBuild1DMipmaps / gluBuild2DMipmaps. The builders scale the image to the
// largest power-of-two size not above it (as GLU's closestFit without proxy textures), then halve
// it level after level down to 1x1, loading each level with glTexImage1D/2D through the GL table
// in the caller's format and type. GLU_UNPACK/PACK row lengths and skips are not honoured; the
// row alignments are.
#include <mygl/glu.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "image.h"

namespace {

using mygl::glu::FloatImage;

// The current pixel-store alignment (GL's default 4 without a loaded GL table).
GLint alignment(GLenum name) {
    GLint value = 4;
    if (glGetIntegerv) glGetIntegerv(name, &value);
    return value;
}

GLint validate(GLenum format, GLenum type, const void* data, int width, int height) {
    if (mygl::glu::componentCount(format) == 0 || mygl::glu::componentBytes(type) == 0) return GLU_INVALID_ENUM;
    if (width < 1 || height < 1 || !data) return GLU_INVALID_VALUE;
    return 0;
}

int powerOfTwoAtMost(int value) {
    int power = 1;
    while (power <= value / 2) power *= 2;
    return power;
}

// Loads every level of `image`, with unpack alignment 1 for the packed levels GLU made itself.
GLint buildMipmaps(GLenum target, GLint internalFormat, int dimensions, FloatImage image, GLenum format, GLenum type) {
    // A GL table without the texture calls (a backend that lacks them) gets an error, not a crash.
    if (!glPixelStorei || (dimensions == 1 ? !glTexImage1D : !glTexImage2D)) {
        return GLU_INVALID_OPERATION;
    }
    const GLint savedAlignment = alignment(GL_UNPACK_ALIGNMENT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bytes;
    for (GLint level = 0;; ++level) {
        bytes.resize(mygl::glu::imageBytes(image.width, image.height, format, type, 1));
        mygl::glu::writeImage(image, type, 1, bytes.data());
        if (dimensions == 1) {
            glTexImage1D(target, level, internalFormat, image.width, 0, format, type, bytes.data());
        } else {
            glTexImage2D(target, level, internalFormat, image.width, image.height, 0, format, type, bytes.data());
        }
        if (image.width == 1 && image.height == 1) break;
        image = mygl::glu::scaleImage(image, image.width > 1 ? image.width / 2 : 1,
                                      image.height > 1 ? image.height / 2 : 1);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, savedAlignment);
    return 0;
}

GLint build(GLenum target, GLint internalFormat, int dimensions, int width, int height, GLenum format, GLenum type,
            const void* data) {
    if (const GLint error = validate(format, type, data, width, height)) return error;
    FloatImage image = mygl::glu::readImage(data, width, height, format, type, alignment(GL_UNPACK_ALIGNMENT));
    const int levelWidth = powerOfTwoAtMost(width), levelHeight = powerOfTwoAtMost(height);
    if (levelWidth != width || levelHeight != height) image = mygl::glu::scaleImage(image, levelWidth, levelHeight);
    return buildMipmaps(target, internalFormat, dimensions, std::move(image), format, type);
}

}  // namespace

extern "C" {

GLint gluScaleImage(GLenum format, GLsizei wIn, GLsizei hIn, GLenum typeIn, const void* dataIn, GLsizei wOut,
                    GLsizei hOut, GLenum typeOut, GLvoid* dataOut) {
    if (mygl::glu::componentBytes(typeOut) == 0) return GLU_INVALID_ENUM;
    if (wIn == 0 || hIn == 0 || wOut == 0 || hOut == 0) return 0;  // as GLU: nothing to do
    if (const GLint error = validate(format, typeIn, dataIn, wIn, hIn)) return error;
    if (wOut < 1 || hOut < 1 || !dataOut) return GLU_INVALID_VALUE;
    const FloatImage in = mygl::glu::readImage(dataIn, wIn, hIn, format, typeIn, alignment(GL_UNPACK_ALIGNMENT));
    mygl::glu::writeImage(mygl::glu::scaleImage(in, wOut, hOut), typeOut, alignment(GL_PACK_ALIGNMENT), dataOut);
    return 0;
}

GLint gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLenum format, GLenum type,
                        const void* data) {
    return build(target, internalFormat, 1, width, 1, format, type, data);
}

GLint gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLenum format, GLenum type,
                        const void* data) {
    return build(target, internalFormat, 2, width, height, format, type, data);
}

}  // extern "C"
