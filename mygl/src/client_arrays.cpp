#include "client_arrays.h"

namespace mygl {

std::size_t componentBytes(GLenum type) {
    switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT: return 2;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
    }
}

const void* ClientArray::element(std::size_t i) const {
    const std::size_t step =
        stride ? static_cast<std::size_t>(stride) : static_cast<std::size_t>(size) * componentBytes(type);
    return static_cast<const unsigned char*>(pointer) + i * step;
}

ClientArray* ClientArrays::find(GLenum name) {
    switch (name) {
    case GL_VERTEX_ARRAY: return &vertex;
    case GL_NORMAL_ARRAY: return &normal;
    case GL_COLOR_ARRAY: return &color;
    case GL_INDEX_ARRAY: return &index;
    case GL_TEXTURE_COORD_ARRAY: return &texCoord;
    case GL_EDGE_FLAG_ARRAY: return &edgeFlag;
    default: return nullptr;
    }
}

}  // namespace mygl
