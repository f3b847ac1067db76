#pragma once
// Client images as gluScaleImage and the mipmap builders see them: any of GL 1.1's formats and
// component types (not the packed 1.2 types, not GL_BITMAP), read and written with a row
// alignment, held in between as normalized floats and scaled with a box filter.
#include <glad/gl.h>

#include <cstddef>
#include <vector>

namespace mygl::glu {

// Components per pixel of `format`, 0 if GLU does not take it.
int componentCount(GLenum format);
// Bytes per component of `type`, 0 if GLU does not take it.
int componentBytes(GLenum type);

struct FloatImage {
    int width = 0, height = 0, components = 0;
    std::vector<float> values;  // row after row, bottom row first, components interleaved
};

// Bytes of one image of width x height in format/type with rows padded to `alignment`.
std::size_t imageBytes(int width, int height, GLenum format, GLenum type, int alignment);
FloatImage readImage(const void* data, int width, int height, GLenum format, GLenum type, int alignment);
void writeImage(const FloatImage& image, GLenum type, int alignment, void* data);
// Each output pixel is the area-weighted average of the input pixels its footprint covers.
FloatImage scaleImage(const FloatImage& image, int width, int height);

}  // namespace mygl::glu
