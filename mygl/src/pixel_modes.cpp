// glPixelTransfer, glPixelMap and glGetPixelMap, and the transfer of colours and depths.
#include "pixel_modes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "compiled.h"

namespace mygl {

glm::vec4 PixelModes::transferColor(glm::vec4 c, const PixelMaps& maps) const {
    for (int i = 0; i < 4; ++i) {
        const float scaled = c[i] * scale[i];
        c[i] = scaled + bias[i];
    }
    if (mapColor) {
        // GL_PIXEL_MAP_R_TO_R .. A_TO_A: the clamped component times (size - 1), rounded to
        // nearest even as the reference rounds it (measured: 106.5 picks 106, 103.5 picks 104);
        // NaN picks entry 0.
        for (int i = 0; i < 4; ++i) {
            const std::vector<float>& map = maps.of(static_cast<GLenum>(GL_PIXEL_MAP_R_TO_R + i));
            const float position = std::clamp(c[i], 0.0f, 1.0f) * static_cast<float>(map.size() - 1);
            c[i] = map[std::isnan(position) ? 0 : static_cast<std::size_t>(std::nearbyint(position))];
        }
    }
    return c;
}

glm::vec4 PixelModes::transferDrawnColor(glm::vec4 c, const PixelMaps& maps) const {
    const bool mapped = mapColor;
    PixelModes scaleAndBias = *this;
    scaleAndBias.mapColor = false;
    c = scaleAndBias.transferColor(c, maps);
    if (!mapped) return c;
    constexpr int kTextureSize = 256;
    for (int i = 0; i < 2; ++i) {
        const std::vector<float>& map = maps.of(static_cast<GLenum>(GL_PIXEL_MAP_R_TO_R + i));
        const int texel = static_cast<int>(std::clamp(std::floor(c[i] * kTextureSize), 0.0f, kTextureSize - 1.0f));
        const float entry = map[static_cast<std::size_t>(texel) * map.size() / kTextureSize];
        c[i] = static_cast<float>(std::lrint(std::clamp(entry, 0.0f, 1.0f) * 255.0f)) * (1.0f / 255.0f);
    }
    return c;
}

namespace {

// floor(value * 2^shift) + offset modulo 256 (every index map's size divides 256): an integer
// index exactly, in 64 bits.
std::uint32_t shiftedIndex(std::int64_t value, int shift, int offset) {
    std::int64_t shifted = 0;
    if (shift >= 0) {
        shifted = shift >= 64 ? 0 : static_cast<std::int64_t>(static_cast<std::uint64_t>(value) << shift);
    } else {
        shifted = value >> std::min(-static_cast<std::int64_t>(shift), std::int64_t{63});
    }
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(shifted) + static_cast<std::uint64_t>(offset)) & 0xFFu;
}

// The same for a float index (its fraction shifts into the integer part).
std::uint32_t shiftedIndex(float value, int shift, int offset) {
    if (!std::isfinite(value)) return shiftedIndex(std::int64_t{0}, shift, offset);
    const double scaled = std::ldexp(static_cast<double>(value), std::clamp(shift, -1100, 1100));
    const double whole = std::fmod(std::floor(scaled), 256.0) + static_cast<double>(offset & 0xFF);
    return static_cast<std::uint32_t>(std::fmod(whole + 512.0, 256.0));
}

}  // namespace

glm::vec4 PixelModes::indexToColor(std::uint32_t value, GLenum type, const PixelMaps& maps) const {
    const bool isSigned = type == GL_BYTE || type == GL_SHORT || type == GL_INT;
    const std::uint32_t index =
        type == GL_FLOAT ? shiftedIndex(std::bit_cast<float>(value), indexShift, indexOffset)
                         : shiftedIndex(isSigned ? std::int64_t{static_cast<std::int32_t>(value)} : std::int64_t{value},
                                        indexShift, indexOffset);
    glm::vec4 c;
    for (int i = 0; i < 4; ++i) {
        const std::vector<float>& map = maps.of(static_cast<GLenum>(GL_PIXEL_MAP_I_TO_R + i));
        const float entry = map[index & static_cast<std::uint32_t>(map.size() - 1)];
        c[i] = std::isnan(entry) ? 0.0f : entry;  // (a NaN given to glPixelMap)
    }
    return c;
}

float PixelModes::transferDepth(float z) const {
    const float scaled = z * depthScale;
    return std::clamp(scaled + depthBias, 0.0f, 1.0f);
}

std::optional<double> pixelModeValue(const PixelModes& m, const PixelMaps& maps, GLenum name) {
    switch (name) {
    case GL_MAP_COLOR: return m.mapColor ? 1.0 : 0.0;
    case GL_MAP_STENCIL: return m.mapStencil ? 1.0 : 0.0;
    case GL_INDEX_SHIFT: return m.indexShift;
    case GL_INDEX_OFFSET: return m.indexOffset;
    case GL_RED_SCALE: return m.scale.r;
    case GL_GREEN_SCALE: return m.scale.g;
    case GL_BLUE_SCALE: return m.scale.b;
    case GL_ALPHA_SCALE: return m.scale.a;
    case GL_RED_BIAS: return m.bias.r;
    case GL_GREEN_BIAS: return m.bias.g;
    case GL_BLUE_BIAS: return m.bias.b;
    case GL_ALPHA_BIAS: return m.bias.a;
    case GL_DEPTH_SCALE: return m.depthScale;
    case GL_DEPTH_BIAS: return m.depthBias;
    case GL_ZOOM_X: return m.zoomX;
    case GL_ZOOM_Y: return m.zoomY;
    case GL_MAX_PIXEL_MAP_TABLE: return PixelMaps::kMaxSize;
    default: break;
    }
    if (name >= GL_PIXEL_MAP_I_TO_I_SIZE && name < GL_PIXEL_MAP_I_TO_I_SIZE + PixelMaps::kCount) {
        return static_cast<double>(maps.maps[name - GL_PIXEL_MAP_I_TO_I_SIZE].size());
    }
    return std::nullopt;
}

namespace {

void pixelTransfer(GLenum name, float value) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    PixelModes& m = s->pixelModes;
    switch (name) {
    case GL_MAP_COLOR: m.mapColor = value != 0.0f; return;
    case GL_MAP_STENCIL: m.mapStencil = value != 0.0f; return;
    case GL_INDEX_SHIFT: m.indexShift = static_cast<int>(value); return;
    case GL_INDEX_OFFSET: m.indexOffset = static_cast<int>(value); return;
    case GL_RED_SCALE: m.scale.r = value; return;
    case GL_GREEN_SCALE: m.scale.g = value; return;
    case GL_BLUE_SCALE: m.scale.b = value; return;
    case GL_ALPHA_SCALE: m.scale.a = value; return;
    case GL_RED_BIAS: m.bias.r = value; return;
    case GL_GREEN_BIAS: m.bias.g = value; return;
    case GL_BLUE_BIAS: m.bias.b = value; return;
    case GL_ALPHA_BIAS: m.bias.a = value; return;
    case GL_DEPTH_SCALE: m.depthScale = value; return;
    case GL_DEPTH_BIAS: m.depthBias = value; return;
    default: return setError(*s, GL_INVALID_ENUM);
    }
}

bool isIndexMap(GLenum map) {
    return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_I_TO_A;
}  // I_TO_I, S_TO_S, I_TO_R..A

// glPixelMap: `convert` turns entry i into the map's float value. Index maps (I_TO_I, S_TO_S)
// keep values as given; colour maps take them as normalized.
template <class T>
void pixelMap(GLenum map, GLsizei size, const T* values) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    // The size before the map, as the reference checks them (a call with both wrong: GL_INVALID_VALUE).
    if (size < 1 || size > PixelMaps::kMaxSize) return setError(*s, GL_INVALID_VALUE);
    // Maps indexed by colour or stencil indices must have a power-of-two size.
    if (isIndexMap(map) && !std::has_single_bit(static_cast<unsigned>(size))) return setError(*s, GL_INVALID_VALUE);
    if (map < GL_PIXEL_MAP_I_TO_I || map > GL_PIXEL_MAP_A_TO_A) return setError(*s, GL_INVALID_ENUM);
    if (!values) return;
    std::vector<float>& target = s->pixelMaps.of(map);
    target.resize(static_cast<std::size_t>(size));
    const bool indices = map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S;
    for (std::size_t i = 0; i < target.size(); ++i) {
        float value = 0.0f;
        if constexpr (std::is_same_v<T, GLfloat>) {
            value = values[i];
        } else {
            constexpr double kMax = std::is_same_v<T, GLuint> ? 4294967295.0 : 65535.0;
            value = indices ? static_cast<float>(values[i]) : static_cast<float>(values[i] / kMax);
        }
        // Stencil indices are rounded to integers, colour values clamped to [0, 1].
        if (map == GL_PIXEL_MAP_S_TO_S)
            value = std::round(value);
        else if (!indices)
            value = std::clamp(value, 0.0f, 1.0f);
        target[i] = value;
    }
}

// A float as the reference's FLOAT_TO_UINT: times 2^32 - 1 in double, truncated through 64 bits
// (so values beyond [0, 1], as index maps hold, wrap).
GLuint floatToUint(float value) {
    const double scaled = std::clamp(static_cast<double>(value) * 4294967295.0, -9.2e18, 9.2e18);
    return static_cast<GLuint>(static_cast<std::int64_t>(std::isnan(scaled) ? 0.0 : scaled));
}

// glGetPixelMap as the reference answers it: unsigned ints FLOAT_TO_UINT of every map but
// S_TO_S, whose floats' bits it copies; unsigned shorts of index maps clamped to [0, 65535] and
// truncated, of colour maps scaled by 65535 and rounded.
template <class T>
void getPixelMap(GLenum map, T* values) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (map < GL_PIXEL_MAP_I_TO_I || map > GL_PIXEL_MAP_A_TO_A) return setError(*s, GL_INVALID_ENUM);
    if (!values) return;
    const std::vector<float>& source = s->pixelMaps.of(map);
    const bool indices = map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S;
    for (std::size_t i = 0; i < source.size(); ++i) {
        if constexpr (std::is_same_v<T, GLfloat>) {
            values[i] = source[i];
        } else if constexpr (std::is_same_v<T, GLuint>) {
            values[i] = map == GL_PIXEL_MAP_S_TO_S ? std::bit_cast<GLuint>(source[i]) : floatToUint(source[i]);
        } else if (indices) {
            values[i] = static_cast<GLushort>(std::clamp(source[i], 0.0f, 65535.0f));
        } else {
            values[i] = static_cast<GLushort>(std::lrint(std::clamp(source[i], 0.0f, 1.0f) * 65535.0f));
        }
    }
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glPixelTransferf, +[](GLenum name, GLfloat value) { pixelTransfer(name, value); }>(),
    listed<gl::glPixelTransferi, +[](GLenum name, GLint value) { pixelTransfer(name, static_cast<float>(value)); }>(),
    listed<gl::glPixelMapfv, +[](GLenum map, GLsizei size, const GLfloat* v) { pixelMap(map, size, v); }>(),
    listed<gl::glPixelMapuiv, +[](GLenum map, GLsizei size, const GLuint* v) { pixelMap(map, size, v); }>(),
    listed<gl::glPixelMapusv, +[](GLenum map, GLsizei size, const GLushort* v) { pixelMap(map, size, v); }>(),
    listed<gl::glGetPixelMapfv, +[](GLenum map, GLfloat* v) { getPixelMap(map, v); }>(),
    listed<gl::glGetPixelMapuiv, +[](GLenum map, GLuint* v) { getPixelMap(map, v); }>(),
    listed<gl::glGetPixelMapusv, +[](GLenum map, GLushort* v) { getPixelMap(map, v); }>(),
};

}  // namespace

std::span<const EntryPoint> pixelModeEntryPoints() { return kEntryPoints; }

}  // namespace mygl
