#include "pixel_store.h"

namespace mygl {

bool isPixelFormat(GLenum format) {
    switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_RGB:
    case GL_RGBA:
    case GL_LUMINANCE:
    case GL_LUMINANCE_ALPHA:
    case GL_BGR:
    case GL_BGRA: return true;
    default: return false;
    }
}

bool isPixelType(GLenum type) {
    switch (type) {
    case GL_BITMAP:
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: return true;
    default: return false;
    }
}

int componentsOf(GLenum format) {
    switch (format) {
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB:
    case GL_BGR: return 3;
    case GL_RGBA:
    case GL_BGRA: return 4;
    default: return 1;
    }
}

std::size_t bytesOfType(GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: return 4;
    default: return 0;
    }
}

ClientLayout clientLayout(int width, GLenum format, GLenum type, const PixelStoreModes& modes) {
    const auto rowPixels = static_cast<std::size_t>(modes.rowLength > 0 ? modes.rowLength : width);
    const auto align = static_cast<std::size_t>(modes.alignment);
    const auto skipPixels = static_cast<std::size_t>(modes.skipPixels),
               skipRows = static_cast<std::size_t>(modes.skipRows);
    if (type == GL_BITMAP) {
        // Rows of bits, padded to the alignment (GL 1.1, 3.6.3: k = a * ceil(l / (8a))).
        const std::size_t stride = (rowPixels + 8 * align - 1) / (8 * align) * align;
        return {stride, skipRows * stride + skipPixels / 8, static_cast<unsigned>(skipPixels % 8)};
    }
    const std::size_t component = bytesOfType(type);
    const std::size_t pixel = component * static_cast<std::size_t>(componentsOf(format));
    std::size_t stride = rowPixels * pixel;
    // Rows start on the alignment unless components are wider than it.
    if (component < align) stride = (stride + align - 1) / align * align;
    return {stride, skipRows * stride + skipPixels * pixel, 0};
}

}  // namespace mygl
