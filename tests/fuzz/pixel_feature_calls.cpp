#include "pixel_feature_calls.h"

#include <cmath>
#include <limits>
#include <string>

namespace fuzz {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr GLenum kInvalidEnums[] = {0x1234, 0xFFFF, 0xFFFFFFFF, GL_RGBA};
constexpr GLenum kIntensity = 0x8049;  // GL_INTENSITY: an internal format of GL 1.1

}  // namespace

void PixelFeatureCalls::emit(std::string_view name, std::vector<double> args) {
    (*emit_)(makeCall(name, std::move(args)));
}

GLenum PixelFeatureCalls::oneOf(std::initializer_list<GLenum> valid) {
    if (random_.chance(invalidEnumRate_)) return kInvalidEnums[random_.integer(0, std::size(kInvalidEnums) - 1)];
    return valid.begin()[random_.integer(0, static_cast<std::int64_t>(valid.size()) - 1)];
}

// `value` as the GL type of suffix `type` (f, d, s, i), or at the badness rate a bad value.
double PixelFeatureCalls::typed(std::string_view type, double value) {
    if (random_.chance(badness_)) {
        if (type == "s") return random_.pick({-32768.0, 32767.0});
        if (type == "i") return random_.pick({-2147483648.0, 2147483647.0});
        return random_.pick({kNaN, kInf, -kInf, 1e30, -1e30, 1e-40, -0.0});
    }
    if (type == "f") return static_cast<float>(value);
    if (type == "d") return value;
    return std::round(value);
}

// An image side: mostly a power of two up to `largest`, now and then any size, at the badness
// rate a bad one (negative, or beyond every maximum).
double PixelFeatureCalls::size(std::int64_t largest) {
    if (random_.chance(badness_)) return random_.pick({-1.0, -100.0, 1e9});
    if (random_.chance(0.2)) return static_cast<double>(random_.integer(0, largest));
    std::int64_t s = 1;
    for (auto k = random_.integer(0, 4); k > 0 && s * 2 <= largest; --k) s *= 2;
    return static_cast<double>(s);
}

double PixelFeatureCalls::dataSeed() {
    const auto seed = random_.integer(0, 1 << 30) * 2;  // even: floats in [0, 1]
    return static_cast<double>(random_.chance(badness_ > 0 ? 0.3 : 0.02) ? seed + 1 : seed);
}

void PixelFeatureCalls::enableOrDisable(GLenum cap, double enableRate) {
    emit(random_.chance(enableRate) ? "glEnable" : "glDisable", {static_cast<double>(cap)});
}

std::pair<GLenum, GLenum> PixelFeatureCalls::imageFormatType(bool texture) {
    // GL_COLOR_INDEX for textures comes from indexImages_ (textureImageCall).
    const GLenum format =
        texture ? oneOf({GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_RED, GL_GREEN, GL_BLUE})
                : oneOf({GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_RED, GL_GREEN, GL_BLUE,
                         GL_COLOR_INDEX, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX});
    GLenum type = oneOf({GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT,
                         GL_INT, GL_FLOAT, GL_FLOAT});
    if ((format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX) && random_.chance(0.2)) type = GL_BITMAP;
    return {format, type};
}

void PixelFeatureCalls::between(const std::function<void(Call)>& emit) {
    emit_ = &emit;
    if (random_.chance(0.35)) {
        switch (random_.integer(0, 9)) {
        case 0:
        case 1:
        case 2: textureCalls(); break;
        case 3:
        case 4: fragmentCalls(); break;
        case 5: stippleCalls(); break;
        case 6:
        case 7: pixelCalls(); break;
        case 8: accumCalls(); break;
        default: stateQuery();
        }
    }
    emit_ = nullptr;
}

// --- textures ------------------------------------------------------------------------------------
void PixelFeatureCalls::textureCalls() {
    if (random_.chance(0.3)) enableOrDisable(oneOf({GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_1D}), 0.7);
    for (auto n = random_.integer(1, 4); n > 0; --n) {
        switch (random_.integer(0, 11)) {
        case 0: {
            const auto count = random_.integer(0, 3);
            emit("glGenTextures", {static_cast<double>(random_.chance(badness_) ? -1 : count)});
            break;
        }
        case 1:
        case 2:
            emit("glBindTexture", {static_cast<double>(oneOf({GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_1D})),
                                   static_cast<double>(random_.integer(0, 4))});
            break;
        case 3:
        case 4: textureImageCall(); break;
        case 5:
        case 6: textureParameterCalls(); break;
        case 7: textureCoordinateCalls(); break;
        case 8: copyTextureCall(); break;
        case 9: textureQuery(); break;
        case 10: {
            std::vector<double> args{static_cast<double>(random_.integer(badness_ > 0 ? -1 : 0, 4))};
            for (int i = 0; i < 4; ++i) args.push_back(static_cast<double>(random_.integer(0, 5)));
            emit("glDeleteTextures", args);
            break;
        }
        default: {
            std::vector<double> args{static_cast<double>(random_.integer(0, 4))};
            for (int i = 0; i < 4; ++i) args.push_back(static_cast<double>(random_.integer(0, 5)));
            for (int i = 0; i < 4; ++i)
                args.push_back(random_.chance(badness_) ? random_.pick({-1.0, 2.0, kNaN}) : random_.unit());
            emit("glPrioritizeTextures", args);
        }
        }
    }
}

void PixelFeatureCalls::textureImageCall() {
    const bool twoD = random_.chance(0.75);
    const GLenum target = twoD ? oneOf({GL_TEXTURE_2D}) : oneOf({GL_TEXTURE_1D});
    const double level = random_.chance(0.7) ? 0 : static_cast<double>(random_.integer(badness_ > 0 ? -1 : 0, 4));
    auto [format, type] = imageFormatType(true);
    if (indexImages_.chance(0.25)) {
        format = GL_COLOR_INDEX;
        type = indexImages_.pick<GLenum>({GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                          GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_BITMAP});
    }
    const bool sub = random_.chance(0.3);
    if (sub) {
        const double w = size(16), h = size(16);
        const double x = static_cast<double>(random_.integer(-1, 8)), y = static_cast<double>(random_.integer(-1, 8));
        if (twoD)
            emit("glTexSubImage2D", {static_cast<double>(target), level, x, y, w, h, static_cast<double>(format),
                                     static_cast<double>(type), dataSeed()});
        else
            emit("glTexSubImage1D", {static_cast<double>(target), level, x, w, static_cast<double>(format),
                                     static_cast<double>(type), dataSeed()});
        return;
    }
    const double internal = random_.chance(invalidEnumRate_)
                                ? random_.pick({0.0, 5.0, static_cast<double>(GL_COLOR_INDEX)})
                                : static_cast<double>(random_.pick<GLenum>(
                                      {1, 2, 3, 4, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, kIntensity, GL_RGB,
                                       GL_RGBA, GL_RGB8, GL_RGBA8, GL_LUMINANCE8, GL_ALPHA8}));
    const double border = random_.chance(0.1) ? 1 : random_.chance(badness_) ? 2 : 0;
    const double w = size(16) + 2 * border, h = size(16) + 2 * border;
    if (twoD)
        emit("glTexImage2D", {static_cast<double>(target), level, internal, w, h, border, static_cast<double>(format),
                              static_cast<double>(type), dataSeed()});
    else
        emit("glTexImage1D", {static_cast<double>(target), level, internal, w, border, static_cast<double>(format),
                              static_cast<double>(type), dataSeed()});
}

void PixelFeatureCalls::textureParameterCalls() {
    const double target = oneOf({GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_1D});
    switch (random_.integer(0, 5)) {
    case 0:
    case 1: {
        const GLenum pname =
            oneOf({GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T});
        const GLenum value = pname == GL_TEXTURE_MIN_FILTER
                                 ? oneOf({GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                          GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR})
                             : pname == GL_TEXTURE_MAG_FILTER ? oneOf({GL_NEAREST, GL_LINEAR})
                                                              : oneOf({GL_CLAMP, GL_REPEAT});
        const auto name = random_.pick<std::string_view>(
            {"glTexParameteri", "glTexParameterf", "glTexParameteriv", "glTexParameterfv"});
        emit(name, {target, static_cast<double>(pname), static_cast<double>(value)});
        break;
    }
    case 2: {
        const bool ints = random_.chance(0.3);
        std::vector<double> args{target, static_cast<double>(oneOf({GL_TEXTURE_BORDER_COLOR}))};
        for (int i = 0; i < 4; ++i) {
            args.push_back(ints ? static_cast<double>(random_.integer(-2147483648LL, 2147483647LL))
                                : typed("f", random_.uniform(-0.2, 1.2)));
        }
        emit(ints ? "glTexParameteriv" : "glTexParameterfv", args);
        break;
    }
    case 3: {
        const GLenum pname = oneOf({GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR});
        if (pname == GL_TEXTURE_ENV_COLOR) {
            std::vector<double> args{GL_TEXTURE_ENV, static_cast<double>(pname)};
            for (int i = 0; i < 4; ++i) args.push_back(typed("f", random_.uniform(-0.2, 1.2)));
            emit("glTexEnvfv", args);
        } else {
            emit(random_.pick<std::string_view>({"glTexEnvi", "glTexEnvf", "glTexEnviv"}),
                 {static_cast<double>(oneOf({GL_TEXTURE_ENV})), static_cast<double>(pname),
                  static_cast<double>(oneOf({GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE}))});
        }
        break;
    }
    case 4: {
        const GLenum coord = oneOf({GL_S, GL_T, GL_R, GL_Q});
        if (random_.chance(0.5)) {
            emit(random_.pick<std::string_view>({"glTexGeni", "glTexGenf", "glTexGend"}),
                 {static_cast<double>(coord), static_cast<double>(oneOf({GL_TEXTURE_GEN_MODE})),
                  static_cast<double>(oneOf({GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP}))});
        } else {
            const auto type = random_.pick<std::string_view>({"f", "d", "i"});
            std::vector<double> args{static_cast<double>(coord),
                                     static_cast<double>(oneOf({GL_OBJECT_PLANE, GL_EYE_PLANE}))};
            for (int i = 0; i < 4; ++i) args.push_back(typed(type, random_.uniform(-2, 2)));
            emit("glTexGen" + std::string(type) + "v", args);
        }
        enableOrDisable(random_.pick<GLenum>({GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q}));
        break;
    }
    default: {  // the texture matrix
        emit("glMatrixMode", {GL_TEXTURE});
        if (random_.chance(0.3))
            emit("glLoadIdentity");
        else if (random_.chance(0.5))
            emit("glScalef", {typed("f", random_.uniform(-3, 3)), typed("f", random_.uniform(-3, 3)), 1});
        else
            emit("glRotatef", {typed("f", random_.uniform(-180, 180)), 0, 0, 1});
        emit("glMatrixMode", {GL_MODELVIEW});
    }
    }
}

void PixelFeatureCalls::textureCoordinateCalls() {
    const auto type = random_.pick<std::string_view>({"s", "i", "f", "d"});
    const auto count = random_.pick({1, 3, 4});
    std::vector<double> args;
    for (int i = 0; i < count; ++i)
        args.push_back(typed(type, i == 3 ? random_.uniform(0.5, 2) : random_.uniform(-2, 2)));
    emit("glTexCoord" + std::to_string(count) + std::string(type) + (random_.chance(0.5) ? "v" : ""), args);
}

void PixelFeatureCalls::copyTextureCall() {
    const bool twoD = random_.chance(0.7);
    const double target = twoD ? oneOf({GL_TEXTURE_2D}) : oneOf({GL_TEXTURE_1D});
    const double x = static_cast<double>(random_.integer(-4, width_)),
                 y = static_cast<double>(random_.integer(-4, height_));
    const double w = size(32), h = size(32);
    if (random_.chance(0.6)) {
        // Formats GL 1.1 takes here only (not 1-4): for others the reference's GL_INVALID_ENUM departs from GL 1.1's
        // GL_INVALID_VALUE.
        const double internal =
            random_.pick<GLenum>({GL_RGB, GL_RGBA, GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA, kIntensity, GL_RGBA8});
        const double border = random_.chance(0.1) ? 1 : 0;
        if (twoD)
            emit("glCopyTexImage2D", {target, 0, internal, x, y, w + 2 * border, h + 2 * border, border});
        else
            emit("glCopyTexImage1D", {target, 0, internal, x, y, w + 2 * border, border});
        return;
    }
    const double xo = static_cast<double>(random_.integer(-1, 4)), yo = static_cast<double>(random_.integer(-1, 4));
    if (twoD)
        emit("glCopyTexSubImage2D", {target, 0, xo, yo, x, y, w, h});
    else
        emit("glCopyTexSubImage1D", {target, 0, xo, x, y, w});
}

void PixelFeatureCalls::textureQuery() {
    const double target = oneOf({GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_1D});
    const double level = static_cast<double>(random_.integer(0, 2));
    switch (random_.integer(0, 6)) {
    case 0:
        // Not GL_TEXTURE_PRIORITY as an integer: the reference's scaling is the rule texture-priority-as-integer.
        emit(random_.chance(0.5) ? "glGetTexParameterfv" : "glGetTexParameteriv",
             {target, static_cast<double>(oneOf({GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S,
                                                 GL_TEXTURE_WRAP_T, GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_PRIORITY}))});
        break;
    case 1:
        emit(random_.chance(0.5) ? "glGetTexLevelParameterfv" : "glGetTexLevelParameteriv",
             {target, level,
              static_cast<double>(oneOf({GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER, GL_TEXTURE_COMPONENTS,
                                         GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE}))});
        break;
    case 2:
        emit(random_.chance(0.5) ? "glGetTexEnvfv" : "glGetTexEnviv",
             {static_cast<double>(oneOf({GL_TEXTURE_ENV})),
              static_cast<double>(oneOf({GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR}))});
        break;
    case 3:
        emit(random_.pick<std::string_view>({"glGetTexGeniv", "glGetTexGenfv", "glGetTexGendv"}),
             {static_cast<double>(oneOf({GL_S, GL_T, GL_R, GL_Q})),
              static_cast<double>(oneOf({GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE}))});
        break;
    case 4: emit("glIsTexture", {static_cast<double>(random_.integer(0, 5))}); break;
    default: {
        const auto [format, type] = imageFormatType(true);
        emit("glGetTexImage", {target, level, static_cast<double>(format), static_cast<double>(type)});
    }
    }
}

// --- per-fragment operations ---------------------------------------------------------------------
void PixelFeatureCalls::fragmentCalls() {
    for (auto n = random_.integer(1, 4); n > 0; --n) {
        const auto comparison = [&] {
            return static_cast<double>(
                oneOf({GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS}));
        };
        const auto stencilOp = [&] {
            return static_cast<double>(oneOf({GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT}));
        };
        switch (random_.integer(0, 11)) {
        case 0:
            emit("glScissor",
                 {static_cast<double>(random_.integer(-4, width_)), static_cast<double>(random_.integer(-4, height_)),
                  random_.chance(badness_) ? -1.0 : static_cast<double>(random_.integer(0, width_ + 4)),
                  static_cast<double>(random_.integer(0, height_ + 4))});
            enableOrDisable(GL_SCISSOR_TEST);
            break;
        case 1:
            emit("glAlphaFunc", {comparison(), typed("f", random_.uniform(-0.2, 1.2))});
            enableOrDisable(GL_ALPHA_TEST);
            break;
        case 2:
            emit("glStencilFunc", {comparison(),
                                   random_.chance(badness_) ? random_.pick({-5.0, 1000.0})
                                                            : static_cast<double>(random_.integer(0, 255)),
                                   static_cast<double>(random_.chance(0.5) ? 255 : random_.integer(0, 4294967295LL))});
            enableOrDisable(GL_STENCIL_TEST);
            break;
        case 3: emit("glStencilOp", {stencilOp(), stencilOp(), stencilOp()}); break;
        case 4:
            emit("glStencilMask", {static_cast<double>(random_.chance(0.5) ? 255 : random_.integer(0, 4294967295LL))});
            break;
        case 5:
            emit("glClearStencil", {static_cast<double>(random_.integer(-2, 300))});
            emit("glClear", {GL_STENCIL_BUFFER_BIT});
            break;
        case 6:
            emit("glBlendFunc",
                 {static_cast<double>(
                      oneOf({GL_ZERO, GL_ONE, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,
                             GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE})),
                  static_cast<double>(oneOf({GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                             GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA}))});
            enableOrDisable(GL_BLEND);
            break;
        case 7:
            emit("glLogicOp",
                 {static_cast<double>(random_.chance(invalidEnumRate_) ? 0x1234 : GL_CLEAR + random_.integer(0, 15))});
            enableOrDisable(GL_COLOR_LOGIC_OP, 0.5);
            break;
        case 8:
            emit("glColorMask", {static_cast<double>(random_.chance(0.7)), static_cast<double>(random_.chance(0.7)),
                                 static_cast<double>(random_.chance(0.7)), static_cast<double>(random_.chance(0.7))});
            break;
        case 9:
            emit("glDrawBuffer", {static_cast<double>(oneOf({GL_FRONT, GL_FRONT, GL_FRONT_LEFT, GL_LEFT,
                                                             GL_FRONT_AND_BACK, GL_NONE, GL_BACK}))});
            break;
        case 10: emit("glReadBuffer", {static_cast<double>(oneOf({GL_FRONT, GL_FRONT_LEFT, GL_LEFT, GL_BACK}))}); break;
        default:
            enableOrDisable(
                oneOf({GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_BLEND, GL_COLOR_LOGIC_OP, GL_DITHER}), 0.3);
        }
    }
}

// --- stipple -------------------------------------------------------------------------------------
void PixelFeatureCalls::stippleCalls() {
    switch (random_.integer(0, 3)) {
    case 0:
        emit("glLineStipple", {static_cast<double>(random_.chance(badness_) ? random_.pick<std::int64_t>({0, -3, 300})
                                                                            : random_.integer(1, 4)),
                               static_cast<double>(random_.integer(0, 65535))});
        enableOrDisable(GL_LINE_STIPPLE);
        break;
    case 1:
        emit("glPolygonStipple", {dataSeed()});
        enableOrDisable(GL_POLYGON_STIPPLE);
        break;
    case 2: emit("glGetPolygonStipple"); break;
    default: enableOrDisable(random_.chance(0.5) ? GL_LINE_STIPPLE : GL_POLYGON_STIPPLE, 0.4);
    }
}

// --- pixel rectangles, raster positions, bitmaps ------------------------------------------------
void PixelFeatureCalls::rasterPosition() {
    const auto type = random_.pick<std::string_view>({"s", "i", "f", "d"});
    const auto count = random_.integer(2, 4);
    std::vector<double> args;
    for (std::int64_t i = 0; i < count; ++i) {
        args.push_back(typed(type, i == 3   ? random_.uniform(0.5, 2)
                                   : i == 2 ? random_.uniform(-1, 1)
                                            : random_.uniform(-1.2, 1.2) * (type == "s" || type == "i" ? 0 : 1)));
    }
    emit("glRasterPos" + std::to_string(count) + std::string(type) + (random_.chance(0.5) ? "v" : ""), args);
}

void PixelFeatureCalls::pixelStateCall() {
    switch (random_.integer(0, 4)) {
    case 0: {
        const GLenum pname =
            oneOf({GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
                   GL_UNPACK_LSB_FIRST, GL_UNPACK_SWAP_BYTES, GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
                   GL_PACK_SKIP_PIXELS, GL_PACK_LSB_FIRST, GL_PACK_SWAP_BYTES});
        const bool alignment = pname == GL_UNPACK_ALIGNMENT || pname == GL_PACK_ALIGNMENT;
        const bool rowLength = pname == GL_UNPACK_ROW_LENGTH || pname == GL_PACK_ROW_LENGTH;
        double value = alignment   ? random_.pick({1.0, 2.0, 4.0, 8.0})
                       : rowLength ? static_cast<double>(random_.pick({0, 0, 3, 17, 40}))
                                   : static_cast<double>(random_.integer(0, 3));
        if (random_.chance(badness_)) value = random_.pick({-1.0, 3.0});
        emit(random_.chance(0.8) ? "glPixelStorei" : "glPixelStoref", {static_cast<double>(pname), value});
        break;
    }
    case 1:
        emit("glPixelZoom", random_.chance(0.3)
                                ? std::vector<double>{1, 1}
                                : std::vector<double>{typed("f", random_.pick({-1.0, 0.5, 2.0, 1.5, -2.5})),
                                                      typed("f", random_.pick({-1.0, 0.5, 2.0, 3.0}))});
        break;
    case 2: {
        const GLenum pname = oneOf({GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE,
                                    GL_GREEN_BIAS, GL_BLUE_SCALE, GL_ALPHA_BIAS, GL_DEPTH_SCALE, GL_DEPTH_BIAS});
        const bool flag = pname == GL_MAP_COLOR || pname == GL_MAP_STENCIL;
        const bool index = pname == GL_INDEX_SHIFT || pname == GL_INDEX_OFFSET;
        const double value =
            random_.chance(0.3)
                ? (pname == GL_RED_SCALE || pname == GL_BLUE_SCALE || pname == GL_DEPTH_SCALE ? 1.0 : 0.0)
            : flag  ? static_cast<double>(random_.integer(0, 1))
            : index ? static_cast<double>(random_.integer(-3, 3))
                    : typed("f", random_.uniform(-0.5, 1.5));
        emit(flag || index ? "glPixelTransferi" : "glPixelTransferf", {static_cast<double>(pname), value});
        break;
    }
    case 3: {
        const GLenum map = oneOf({GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_G,
                                  GL_PIXEL_MAP_I_TO_B, GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G,
                                  GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A});
        // I_TO_I only with a power-of-two size: the rule pixel-map-i-to-i-any-size.
        double mapSize = static_cast<double>(random_.pick({1, 2, 4, 8, 16}));
        if (random_.chance(badness_)) mapSize = random_.pick({0.0, -1.0, 3.0});
        const auto name = random_.pick<std::string_view>({"glPixelMapfv", "glPixelMapuiv", "glPixelMapusv"});
        std::vector<double> args{static_cast<double>(map), mapSize};
        for (int i = 0; i < 16; ++i) {
            args.push_back(name == "glPixelMapfv"
                               ? typed("f", random_.uniform(-0.2, 1.2) * (map <= GL_PIXEL_MAP_S_TO_S ? 20 : 1))
                           : name == "glPixelMapuiv" ? static_cast<double>(random_.integer(0, 4294967295LL))
                                                     : static_cast<double>(random_.integer(0, 65535)));
        }
        emit(name, args);
        break;
    }
    default:
        emit(random_.pick<std::string_view>({"glGetPixelMapfv", "glGetPixelMapuiv", "glGetPixelMapusv"}),
             {static_cast<double>(oneOf({GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R,
                                         GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_A_TO_A}))});
    }
}

void PixelFeatureCalls::pixelCalls() {
    for (auto n = random_.integer(1, 4); n > 0; --n) {
        switch (random_.integer(0, 7)) {
        case 0:
        case 1: pixelStateCall(); break;
        case 2: rasterPosition(); break;
        case 3: {
            rasterPosition();
            const auto [format, type] = imageFormatType(false);
            emit("glDrawPixels",
                 {size(24), size(24), static_cast<double>(format), static_cast<double>(type), dataSeed()});
            break;
        }
        case 4:
            emit("glCopyPixels",
                 {static_cast<double>(random_.integer(-4, width_)), static_cast<double>(random_.integer(-4, height_)),
                  size(32), size(32), static_cast<double>(oneOf({GL_COLOR, GL_COLOR, GL_DEPTH, GL_STENCIL}))});
            break;
        case 5: {
            rasterPosition();
            const double w = size(16), h = size(16);
            emit("glBitmap", {w, h, typed("f", random_.uniform(-2, 2)), typed("f", random_.uniform(-2, 2)),
                              typed("f", random_.uniform(-8, 8)), typed("f", random_.uniform(-8, 8)), dataSeed()});
            break;
        }
        default: {
            const auto [format, type] = imageFormatType(false);
            emit("glReadPixels",
                 {static_cast<double>(random_.integer(-4, width_)), static_cast<double>(random_.integer(-4, height_)),
                  size(32), size(32), static_cast<double>(format), static_cast<double>(type)});
        }
        }
    }
}

// --- accumulation buffer -------------------------------------------------------------------------
void PixelFeatureCalls::accumCalls() {
    if (random_.chance(0.4)) {
        emit("glClearAccum", {typed("f", random_.uniform(-1, 1)), typed("f", random_.uniform(-1, 1)),
                              typed("f", random_.uniform(-1, 1)), typed("f", random_.uniform(-1, 1))});
        emit("glClear", {GL_ACCUM_BUFFER_BIT});
    }
    for (auto n = random_.integer(1, 3); n > 0; --n) {
        emit("glAccum", {static_cast<double>(oneOf({GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD})),
                         typed("f", random_.uniform(-1.5, 1.5))});
    }
}

void PixelFeatureCalls::stateQuery() {
    const GLenum name = oneOf({GL_TEXTURE_1D,
                               GL_TEXTURE_2D,
                               GL_TEXTURE_BINDING_1D,
                               GL_TEXTURE_BINDING_2D,
                               GL_TEXTURE_GEN_S,
                               GL_TEXTURE_GEN_Q,
                               GL_SCISSOR_BOX,
                               GL_SCISSOR_TEST,
                               GL_ALPHA_TEST_FUNC,
                               GL_ALPHA_TEST_REF,
                               GL_STENCIL_FUNC,
                               GL_STENCIL_REF,
                               GL_STENCIL_VALUE_MASK,
                               GL_STENCIL_FAIL,
                               GL_STENCIL_PASS_DEPTH_PASS,
                               GL_STENCIL_WRITEMASK,
                               GL_STENCIL_CLEAR_VALUE,
                               GL_BLEND_SRC,
                               GL_BLEND_DST,
                               GL_LOGIC_OP_MODE,
                               GL_COLOR_LOGIC_OP,
                               GL_COLOR_WRITEMASK,
                               GL_DRAW_BUFFER,
                               GL_READ_BUFFER,
                               GL_LINE_STIPPLE_PATTERN,
                               GL_LINE_STIPPLE_REPEAT,
                               GL_POLYGON_STIPPLE,
                               GL_CURRENT_RASTER_POSITION,
                               GL_CURRENT_RASTER_POSITION_VALID,
                               GL_CURRENT_RASTER_COLOR,
                               GL_CURRENT_RASTER_TEXTURE_COORDS,
                               GL_ZOOM_X,
                               GL_ZOOM_Y,
                               GL_UNPACK_ROW_LENGTH,
                               GL_PACK_SKIP_ROWS,
                               GL_MAP_COLOR,
                               GL_INDEX_SHIFT,
                               GL_RED_SCALE,
                               GL_PIXEL_MAP_I_TO_R_SIZE,
                               GL_ACCUM_CLEAR_VALUE,
                               GL_ACCUM_RED_BITS,
                               GL_MAX_TEXTURE_SIZE,
                               GL_TEXTURE_ENV_MODE,
                               GL_TEXTURE_ENV_COLOR});
    emit(random_.pick<std::string_view>(
             {"glGetBooleanv", "glGetIntegerv", "glGetFloatv", "glGetDoublev", "glIsEnabled"}),
         {static_cast<double>(name)});
}

}  // namespace fuzz
