#include "image_calls.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

#include "gl_enum_names.h"

namespace fuzz {
namespace {

using Args = std::vector<double>;

GLenum E(double v) { return std::isnan(v) ? 0 : static_cast<GLenum>(std::clamp(v, 0.0, 4294967295.0)); }
GLint I(double v) { return std::isnan(v) ? 0 : static_cast<GLint>(std::clamp(v, -2147483648.0, 2147483647.0)); }
GLfloat F(double v) { return static_cast<GLfloat>(v); }

constexpr std::size_t kImageBytesMax = std::size_t{256} << 20;

// What an image argument holds: its size, format and type.
struct Shape {
    std::int64_t width, height;
    GLenum format, type;
};

struct Layout {
    GLint rowLength, skipRows, skipPixels, alignment;
};

Layout layout(bool pack) {
    Layout l{0, 0, 0, 4};
    glGetIntegerv(pack ? GL_PACK_ROW_LENGTH : GL_UNPACK_ROW_LENGTH, &l.rowLength);
    glGetIntegerv(pack ? GL_PACK_SKIP_ROWS : GL_UNPACK_SKIP_ROWS, &l.skipRows);
    glGetIntegerv(pack ? GL_PACK_SKIP_PIXELS : GL_UNPACK_SKIP_PIXELS, &l.skipPixels);
    glGetIntegerv(pack ? GL_PACK_ALIGNMENT : GL_UNPACK_ALIGNMENT, &l.alignment);
    l.alignment = std::clamp(l.alignment, 1, 8);
    return l;
}

int componentsOf(GLenum format) {
    switch (format) {
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB: return 3;
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE: return 1;
    default: return 4;  // RGBA, and the most for a format GL rejects
    }
}

int typeBytes(GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: return 2;
    default: return 4;  // int, uint, float, and the most for a type GL rejects
    }
}

// The bytes from the image's start up to and including pixel (column, row) of the rectangle.
std::size_t bytesThrough(const Shape& s, const Layout& l, std::int64_t column, std::int64_t row) {
    const std::int64_t length = l.rowLength > 0 ? l.rowLength : s.width;
    const std::int64_t a = l.alignment;
    if (s.type == GL_BITMAP) {
        const std::int64_t rowBytes = ((length + 7) / 8 + a - 1) / a * a;
        return static_cast<std::size_t>((l.skipRows + row) * rowBytes + (l.skipPixels + column) / 8 + 1);
    }
    const std::int64_t size = typeBytes(s.type), group = size * componentsOf(s.format);
    const std::int64_t rowBytes = size >= a ? length * group : (length * group + a - 1) / a * a;
    return static_cast<std::size_t>((l.skipRows + row) * rowBytes + (l.skipPixels + column + 1) * group);
}

// The bytes GL reads or writes for the whole rectangle; at least 4.
std::size_t imageBytes(const Shape& s, const Layout& l) {
    if (s.width <= 0 || s.height <= 0) return 4;
    return std::max<std::size_t>(4, bytesThrough(s, l, s.width - 1, s.height - 1));
}

std::uint32_t mix(std::uint32_t seed, std::size_t i) {
    std::uint32_t h = static_cast<std::uint32_t>(i) * 2654435761u + seed;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    return h ^ (h >> 15);
}

bool saneFloats(std::uint32_t seed, GLenum type) { return type == GL_FLOAT && seed % 2 == 0; }

std::vector<std::uint8_t> imageData(std::uint32_t seed, GLenum type, std::size_t bytes) {
    std::vector<std::uint8_t> data(bytes);
    if (saneFloats(seed, type)) {
        for (std::size_t i = 0; i + 4 <= bytes; i += 4) {
            const GLfloat v = static_cast<GLfloat>(mix(seed, i / 4) % 1001) / 1000.0f;
            std::memcpy(&data[i], &v, 4);
        }
    } else {
        for (std::size_t i = 0; i < bytes; ++i) data[i] = static_cast<std::uint8_t>(mix(seed, i));
    }
    return data;
}

// The C statements declaring `d`, the image data of seed `seed`, as imageData makes it.
std::string declareData(std::uint32_t seed, GLenum type, std::size_t bytes) {
    char text[512];
    const char* hash = "GLuint h = i * 2654435761u + %uu; h ^= h >> 13; h *= 0x5bd1e995u; h ^= h >> 15;";
    char hashed[160];
    std::snprintf(hashed, sizeof hashed, hash, seed);
    if (saneFloats(seed, type)) {
        std::snprintf(
            text, sizeof text,
            "static GLfloat d[%zu]; for (GLuint i = 0; i < %zu; ++i) { %s d[i] = (GLfloat)(h %% 1001) / 1000.0f; } ",
            (bytes + 3) / 4, bytes / 4, hashed);
    } else {
        std::snprintf(text, sizeof text,
                      "static GLubyte d[%zu]; for (GLuint i = 0; i < %zu; ++i) { %s d[i] = (GLubyte)h; } ", bytes,
                      bytes, hashed);
    }
    return text;
}

std::string printEnum(double v) {
    const std::string name = enumName(E(v));
    if (!name.empty()) return name;
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%X", E(v));
    return hex;
}

std::string printFloat(double v) {
    if (std::isnan(v)) return "NAN";
    if (std::isinf(v)) return v > 0 ? "INFINITY" : "-INFINITY";
    char text[48];
    std::snprintf(text, sizeof text, "%.9gf", static_cast<double>(F(v)));
    return text;
}

// The scalar arguments as C: one letter per argument, e (enum), i (int), f (float).
std::string printArguments(const Args& a, std::string_view kinds) {
    std::string s;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        s += i ? ", " : "";
        s += kinds[i] == 'e' ? printEnum(a[i]) : kinds[i] == 'f' ? printFloat(a[i]) : std::to_string(I(a[i]));
    }
    return s;
}

// One image function: `kinds` its scalar arguments, `shape` the image they describe, `call` the GL call.
struct Description {
    std::string_view name;
    std::string_view kinds;
    bool reads;  // GL reads the image (unpack); else writes it (pack)
    Shape (*shape)(const Args&, int width, int height);
    void (*call)(const Args&, void* image);
};

// glGetTexImage's image size, without its border, when its target and level are valid (an error
// call writes nothing).
Shape textureLevel(const Args& a, int, int) {
    Shape s{0, 0, E(a[2]), E(a[3])};
    const GLenum target = E(a[0]);
    if ((target != GL_TEXTURE_1D && target != GL_TEXTURE_2D) || I(a[1]) < 0 || I(a[1]) > 14) return s;
    GLint w = 0, h = 0, border = 0;
    glGetTexLevelParameteriv(target, I(a[1]), GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, I(a[1]), GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(target, I(a[1]), GL_TEXTURE_BORDER, &border);
    s.width = w - 2 * border;
    s.height = target == GL_TEXTURE_1D ? std::min(h, 1) : h - 2 * border;
    return s;
}

// glReadPixels writes only the part of its rectangle inside the framebuffer.
Shape readRectangle(const Args& a, int, int) { return {I(a[2]), I(a[3]), E(a[4]), E(a[5])}; }

const Description kDescriptions[] = {
    {"glTexImage1D", "eiiiiee", true,
     [](const Args& a, int, int) {
         return Shape{I(a[3]), 1, E(a[5]), E(a[6])};
     },
     [](const Args& a, void* d) { glTexImage1D(E(a[0]), I(a[1]), I(a[2]), I(a[3]), I(a[4]), E(a[5]), E(a[6]), d); }},
    {"glTexImage2D", "eiiiiiee", true,
     [](const Args& a, int, int) {
         return Shape{I(a[3]), I(a[4]), E(a[6]), E(a[7])};
     },
     [](const Args& a, void* d) {
         glTexImage2D(E(a[0]), I(a[1]), I(a[2]), I(a[3]), I(a[4]), I(a[5]), E(a[6]), E(a[7]), d);
     }},
    {"glTexSubImage1D", "eiiiee", true,
     [](const Args& a, int, int) {
         return Shape{I(a[3]), 1, E(a[4]), E(a[5])};
     },
     [](const Args& a, void* d) { glTexSubImage1D(E(a[0]), I(a[1]), I(a[2]), I(a[3]), E(a[4]), E(a[5]), d); }},
    {"glTexSubImage2D", "eiiiiiee", true,
     [](const Args& a, int, int) {
         return Shape{I(a[4]), I(a[5]), E(a[6]), E(a[7])};
     },
     [](const Args& a, void* d) {
         glTexSubImage2D(E(a[0]), I(a[1]), I(a[2]), I(a[3]), I(a[4]), I(a[5]), E(a[6]), E(a[7]), d);
     }},
    {"glDrawPixels", "iiee", true,
     [](const Args& a, int, int) {
         return Shape{I(a[0]), I(a[1]), E(a[2]), E(a[3])};
     },
     [](const Args& a, void* d) { glDrawPixels(I(a[0]), I(a[1]), E(a[2]), E(a[3]), d); }},
    {"glBitmap", "iiffff", true,
     [](const Args& a, int, int) {
         return Shape{I(a[0]), I(a[1]), GL_COLOR_INDEX, GL_BITMAP};
     },
     [](const Args& a, void* d) {
         glBitmap(I(a[0]), I(a[1]), F(a[2]), F(a[3]), F(a[4]), F(a[5]), static_cast<const GLubyte*>(d));
     }},
    {"glPolygonStipple", "", true,
     [](const Args&, int, int) {
         return Shape{32, 32, GL_COLOR_INDEX, GL_BITMAP};
     },
     [](const Args&, void* d) { glPolygonStipple(static_cast<const GLubyte*>(d)); }},
    {"glReadPixels", "iiiiee", false, readRectangle,
     [](const Args& a, void* d) { glReadPixels(I(a[0]), I(a[1]), I(a[2]), I(a[3]), E(a[4]), E(a[5]), d); }},
    {"glGetPolygonStipple", "", false,
     [](const Args&, int, int) {
         return Shape{32, 32, GL_COLOR_INDEX, GL_BITMAP};
     },
     [](const Args&, void* d) { glGetPolygonStipple(static_cast<GLubyte*>(d)); }},
    {"glGetTexImage", "eiee", false, textureLevel,
     [](const Args& a, void* d) { glGetTexImage(E(a[0]), I(a[1]), E(a[2]), E(a[3]), d); }},
};

// glReadPixels' bytes: up to its last pixel inside the framebuffer (GL writes no others).
std::size_t readPixelsExtent(const Args& a, const Shape& s, const Layout& l, int width, int height) {
    const std::int64_t x = I(a[0]), y = I(a[1]);
    const std::int64_t lastColumn = std::min<std::int64_t>(x + s.width, width) - 1 - x;
    const std::int64_t lastRow = std::min<std::int64_t>(y + s.height, height) - 1 - y;
    if (s.width <= 0 || s.height <= 0 || lastColumn < std::max<std::int64_t>(0, -x) ||
        lastRow < std::max<std::int64_t>(0, -y))
        return 4;
    return std::max<std::size_t>(4, bytesThrough(s, l, lastColumn, lastRow));
}

template <std::size_t N>
void run(const Call& call, std::uint32_t index, int width, int height, Answers& answers) {
    const Description& d = kDescriptions[N];
    const Args& a = call.args;
    const Shape shape = d.shape(a, width, height);
    const Layout l = layout(!d.reads);
    const std::size_t bytes =
        d.name == "glReadPixels" ? readPixelsExtent(a, shape, l, width, height) : imageBytes(shape, l);
    if (bytes > kImageBytesMax) return;  // the generator keeps images smaller; only a hand-edited stream gets here
    if (d.reads) {
        const auto seed = static_cast<std::uint32_t>(I(a[d.kinds.size()]));
        std::vector<std::uint8_t> data = imageData(seed, shape.type, bytes);
        d.call(a, data.data());
        return;
    }
    std::vector<std::uint8_t> buffer(bytes, 0x5A);  // untouched bytes show
    d.call(a, buffer.data());
    const bool depth = shape.format == GL_DEPTH_COMPONENT;
    answers.push_back({depth ? AnswerKind::Depth : AnswerKind::Color, index, std::move(buffer)});
}

template <std::size_t N>
std::string print(const Call& call) {
    const Description& d = kDescriptions[N];
    const Args& a = call.args;
    const std::string arguments = printArguments(a, d.kinds) + (d.kinds.empty() ? "" : ", ");
    if (!d.reads) return "{ static GLubyte pixels[1 << 24]; " + std::string(d.name) + "(" + arguments + "pixels); }";
    // The data as the default unpack state needs it; a stream that changes the state may need more.
    const Shape shape = d.shape(a, 0, 0);
    const std::size_t bytes = imageBytes(shape, Layout{0, 0, 0, 4}) + 4096;
    return "{ " + declareData(static_cast<std::uint32_t>(I(a[d.kinds.size()])), shape.type, bytes) +
           std::string(d.name) + "(" + arguments + "d); }";
}

template <std::size_t... N>
std::vector<ImageFunction> makeFunctions(std::index_sequence<N...>) {
    return {ImageFunction{kDescriptions[N].name, kDescriptions[N].kinds.size() + (kDescriptions[N].reads ? 1 : 0),
                          &run<N>, &print<N>}...};
}

}  // namespace

const std::vector<ImageFunction>& imageFunctions() {
    static const std::vector<ImageFunction> functions =
        makeFunctions(std::make_index_sequence<std::size(kDescriptions)>());
    return functions;
}

}  // namespace fuzz
