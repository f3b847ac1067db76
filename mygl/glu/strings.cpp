// gluErrorString for GL and GLU errors, gluGetString and gluCheckExtension.
#include <mygl/glu.h>

#include <cstring>

namespace {

const GLubyte* text(const char* s) { return reinterpret_cast<const GLubyte*>(s); }

}  // namespace

extern "C" {

const GLubyte* gluErrorString(GLenum error) {
    switch (error) {
    case GL_NO_ERROR: return text("no error");
    case GL_INVALID_ENUM: return text("invalid enumerant");
    case GL_INVALID_VALUE: return text("invalid value");
    case GL_INVALID_OPERATION: return text("invalid operation");
    case GL_STACK_OVERFLOW: return text("stack overflow");
    case GL_STACK_UNDERFLOW: return text("stack underflow");
    case GL_OUT_OF_MEMORY: return text("out of memory");
    case 0x0506: return text("invalid framebuffer operation");  // GL 3.0's, reported by newer GLs
    case 0x8031: return text("table too large");                // GL_TABLE_TOO_LARGE (imaging)
    case GLU_INVALID_ENUM: return text("invalid enumerant");
    case GLU_INVALID_VALUE: return text("invalid value");
    case GLU_OUT_OF_MEMORY: return text("out of memory");
    case GLU_INCOMPATIBLE_GL_VERSION: return text("incompatible gl version");
    case GLU_INVALID_OPERATION: return text("invalid operation");
    case GLU_TESS_MISSING_BEGIN_POLYGON: return text("gluTessBeginPolygon must come before this call");
    case GLU_TESS_MISSING_BEGIN_CONTOUR: return text("gluTessBeginContour must come before this call");
    case GLU_TESS_MISSING_END_POLYGON: return text("gluTessEndPolygon must come before this call");
    case GLU_TESS_MISSING_END_CONTOUR: return text("gluTessEndContour must come before this call");
    case GLU_TESS_COORD_TOO_LARGE: return text("a tessellation coordinate is too large or not finite");
    case GLU_TESS_NEED_COMBINE_CALLBACK: return text("intersecting contours need a combine callback");
    default: return nullptr;
    }
}

const GLubyte* gluGetString(GLenum name) {
    switch (name) {
    case GLU_VERSION: return text("1.3");
    case GLU_EXTENSIONS: return text("");
    default: return nullptr;
    }
}

// True if extName is one of the space-separated names in extString (whole names only).
GLboolean gluCheckExtension(const GLubyte* extName, const GLubyte* extString) {
    if (!extName || !extString) return GL_FALSE;
    const char* name = reinterpret_cast<const char*>(extName);
    const std::size_t length = std::strlen(name);
    if (length == 0 || std::strchr(name, ' ')) return GL_FALSE;
    const char* cursor = reinterpret_cast<const char*>(extString);
    while (*cursor) {
        const std::size_t word = std::strcspn(cursor, " ");
        if (word == length && std::strncmp(cursor, name, length) == 0) return GL_TRUE;
        cursor += word;
        while (*cursor == ' ') ++cursor;
    }
    return GL_FALSE;
}

}  // extern "C"
