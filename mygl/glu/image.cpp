#include "image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace mygl::glu {
namespace {

template <class T>
float normalized(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    if constexpr (std::is_floating_point_v<T>) {
        return value;
    } else {
        const double scaled = static_cast<double>(value) / static_cast<double>(std::numeric_limits<T>::max());
        return static_cast<float>(std::max(scaled, -1.0));  // signed: -max-1 maps to -1 as well
    }
}

template <class T>
void store(float value, unsigned char* bytes) {
    T out;
    if constexpr (std::is_floating_point_v<T>) {
        out = value;
    } else {
        const double low = std::is_signed_v<T> ? -1.0 : 0.0;
        const double clamped = std::clamp(static_cast<double>(value), low, 1.0);
        out = static_cast<T>(std::lround(clamped * static_cast<double>(std::numeric_limits<T>::max())));
    }
    std::memcpy(bytes, &out, sizeof out);
}

float readComponent(GLenum type, const unsigned char* bytes) {
    switch (type) {
    case GL_UNSIGNED_BYTE: return normalized<std::uint8_t>(bytes);
    case GL_BYTE: return normalized<std::int8_t>(bytes);
    case GL_UNSIGNED_SHORT: return normalized<std::uint16_t>(bytes);
    case GL_SHORT: return normalized<std::int16_t>(bytes);
    case GL_UNSIGNED_INT: return normalized<std::uint32_t>(bytes);
    case GL_INT: return normalized<std::int32_t>(bytes);
    default: return normalized<float>(bytes);
    }
}

void writeComponent(GLenum type, float value, unsigned char* bytes) {
    switch (type) {
    case GL_UNSIGNED_BYTE: return store<std::uint8_t>(value, bytes);
    case GL_BYTE: return store<std::int8_t>(value, bytes);
    case GL_UNSIGNED_SHORT: return store<std::uint16_t>(value, bytes);
    case GL_SHORT: return store<std::int16_t>(value, bytes);
    case GL_UNSIGNED_INT: return store<std::uint32_t>(value, bytes);
    case GL_INT: return store<std::int32_t>(value, bytes);
    default: return store<float>(value, bytes);
    }
}

std::size_t rowBytes(int width, int components, int bytes, int alignment) {
    const std::size_t raw = static_cast<std::size_t>(width) * components * bytes;
    const std::size_t a = alignment > 0 ? static_cast<std::size_t>(alignment) : 1;
    return (raw + a - 1) / a * a;
}

// The part of source pixel `source` that the footprint [begin, end) covers.
double overlap(int source, double begin, double end) {
    return std::max(0.0, std::min(end, source + 1.0) - std::max(begin, static_cast<double>(source)));
}

}  // namespace

int componentCount(GLenum format) {
    switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB:
    case 0x80E0: return 3;  // GL_BGR
    case GL_RGBA:
    case 0x80E1: return 4;  // GL_BGRA
    default: return 0;
    }
}

int componentBytes(GLenum type) {
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

std::size_t imageBytes(int width, int height, GLenum format, GLenum type, int alignment) {
    return rowBytes(width, componentCount(format), componentBytes(type), alignment) * static_cast<std::size_t>(height);
}

FloatImage readImage(const void* data, int width, int height, GLenum format, GLenum type, int alignment) {
    FloatImage image{width, height, componentCount(format), {}};
    const int bytes = componentBytes(type);
    const std::size_t stride = rowBytes(width, image.components, bytes, alignment);
    image.values.resize(static_cast<std::size_t>(width) * height * image.components);
    const auto* source = static_cast<const unsigned char*>(data);
    std::size_t out = 0;
    for (int y = 0; y < height; ++y) {
        const unsigned char* row = source + stride * y;
        for (int k = 0; k < width * image.components; ++k) image.values[out++] = readComponent(type, row + k * bytes);
    }
    return image;
}

void writeImage(const FloatImage& image, GLenum type, int alignment, void* data) {
    const int bytes = componentBytes(type);
    const std::size_t stride = rowBytes(image.width, image.components, bytes, alignment);
    auto* target = static_cast<unsigned char*>(data);
    std::size_t in = 0;
    for (int y = 0; y < image.height; ++y) {
        unsigned char* row = target + stride * y;
        for (int k = 0; k < image.width * image.components; ++k)
            writeComponent(type, image.values[in++], row + k * bytes);
    }
}

FloatImage scaleImage(const FloatImage& image, int width, int height) {
    FloatImage out{width, height, image.components, {}};
    out.values.assign(static_cast<std::size_t>(width) * height * image.components, 0.0f);
    const double sx = static_cast<double>(image.width) / width, sy = static_cast<double>(image.height) / height;
    std::vector<double> sum(image.components);
    for (int y = 0; y < height; ++y) {
        const double y0 = y * sy, y1 = (y + 1) * sy;
        for (int x = 0; x < width; ++x) {
            const double x0 = x * sx, x1 = (x + 1) * sx;
            std::fill(sum.begin(), sum.end(), 0.0);
            double area = 0.0;
            for (int v = static_cast<int>(y0); v < image.height && v < y1; ++v) {
                const double wy = overlap(v, y0, y1);
                for (int u = static_cast<int>(x0); u < image.width && u < x1; ++u) {
                    const double weight = wy * overlap(u, x0, x1);
                    const float* pixel =
                        &image.values[(static_cast<std::size_t>(v) * image.width + u) * image.components];
                    for (int c = 0; c < image.components; ++c) sum[c] += weight * pixel[c];
                    area += weight;
                }
            }
            float* target = &out.values[(static_cast<std::size_t>(y) * width + x) * image.components];
            for (int c = 0; c < image.components; ++c)
                target[c] = area > 0.0 ? static_cast<float>(sum[c] / area) : 0.0f;
        }
    }
    return out;
}

}  // namespace mygl::glu
