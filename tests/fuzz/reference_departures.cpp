#include "reference_departures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string_view>

namespace fuzz {
namespace {

// Float values that round to an int: below 2^31 - 0.5 in magnitude.
constexpr double kIntLimit = 2147483647.0;

// The digit after the prefix of "glVertex3f", "glColor4ub": the number of components.
int components(std::string_view name, std::string_view prefix) { return name[prefix.size()] - '0'; }

// Whether a glColor4* call's alpha converts to exactly 1 (the largest value of an integer type).
bool setsAlphaOne(std::string_view name, double alpha) {
    const std::string_view type = name.substr(8, name.ends_with("v") ? name.size() - 9 : std::string_view::npos);
    if (type == "f" || type == "d") return alpha == 1.0;
    if (type == "b") return alpha == 127;
    if (type == "ub") return alpha == 255;
    if (type == "s") return alpha == 32767;
    if (type == "us") return alpha == 65535;
    if (type == "i") return alpha == 2147483647.0;
    return alpha == 4294967295.0;  // ui
}

bool isIntegerMatrixQuery(const Call& call, const StreamContext&) {
    if (functionName(call) != "glGetIntegerv") return false;
    const auto pname = static_cast<GLenum>(call.args[0]);
    return pname == GL_MODELVIEW_MATRIX || pname == GL_PROJECTION_MATRIX || pname == GL_TEXTURE_MATRIX;
}

bool isIntegerQueryOutOfRange(const Call& call, const StreamContext& c) {
    if (functionName(call) != "glGetIntegerv") return false;
    switch (static_cast<GLenum>(call.args[0])) {
    case GL_CURRENT_COLOR: return c.colorBeyondUnit;
    case GL_CURRENT_NORMAL: return c.normalBeyondUnit;
    case GL_CURRENT_TEXTURE_COORDS: return c.texCoordBeyondInt;
    case GL_LINE_WIDTH: return c.lineWidthBeyondInt;
    case GL_POINT_SIZE: return c.pointSizeBeyondInt;
    default: return false;
    }
}

// Whether any of the call's arguments, as the float the reference stores, lies outside
// [-limit, limit] or is NaN. Normalized (colour, normal) integer types convert into range.
bool anyBeyond(std::string_view name, const std::vector<double>& args, double limit, bool normalized) {
    const bool floating = name.ends_with("f") || name.ends_with("d") || name.ends_with("fv") || name.ends_with("dv");
    if (normalized && !floating) return false;
    return std::any_of(args.begin(), args.end(), [&](double v) { return !(std::abs(static_cast<float>(v)) <= limit); });
}

bool isNonCanonicalBoolean(const Call& call, const StreamContext&) {
    const std::string_view name = functionName(call);
    return (name == "glDepthMask" || name.starts_with("glEdgeFlag")) && call.args[0] != GL_FALSE &&
           call.args[0] != GL_TRUE;
}

bool isColor3fKeepingAlpha(const Call& call, const StreamContext& context) {
    const std::string_view name = functionName(call);
    return (name == "glColor3f" || name == "glColor3fv") && context.alphaNotOneSinceFlush;
}

bool growsLineLoopFormat(const Call& call, const StreamContext& c) {
    if (!c.insideBegin || c.mode != GL_LINE_LOOP || c.verticesInBlock == 0) return false;
    const std::string_view name = functionName(call);
    const StreamContext::Attributes& first = c.atFirstVertex;
    if (name.starts_with("glVertex")) return components(name, "glVertex") > first.vertexSize;
    if (name.starts_with("glColor")) return components(name, "glColor") > first.colorSize;
    if (name.starts_with("glNormal")) return !first.normal;
    if (name.starts_with("glTexCoord")) return !first.texCoord;
    if (name.starts_with("glEdgeFlag")) return !first.edgeFlag;
    return false;
}

bool readPixelsSumOverflows(const Call& call, const StreamContext&) {
    if (functionName(call) != "glReadPixels") return false;
    constexpr std::int64_t kIntMax = std::numeric_limits<GLint>::max();
    const auto at = [&](int i) { return static_cast<std::int64_t>(call.args[i]); };
    return at(0) + at(2) > kIntMax || at(1) + at(3) > kIntMax;
}

bool readsUnknownFormat(const Call& call, const StreamContext&) {
    if (functionName(call) != "glReadPixels" || call.args[2] < 0 || call.args[3] < 0) return false;
    constexpr GLenum kFormats[] = {GL_COLOR_INDEX, GL_STENCIL_INDEX, GL_DEPTH_COMPONENT, GL_RED,
                                   GL_GREEN,       GL_BLUE,          GL_ALPHA,           GL_RGB,
                                   GL_RGBA,        GL_LUMINANCE,     GL_LUMINANCE_ALPHA};
    return std::find(std::begin(kFormats), std::end(kFormats), static_cast<GLenum>(call.args[4])) == std::end(kFormats);
}

bool togglesLightUnderEnableBit(const Call& call, const StreamContext& context) {
    const std::string_view name = functionName(call);
    if (name != "glEnable" && name != "glDisable") return false;
    const auto cap = static_cast<GLenum>(call.args[0]);
    if (cap < GL_LIGHT0 || cap > GL_LIGHT7) return false;
    return std::any_of(context.attribStack.begin(), context.attribStack.end(), [](const StreamContext::Pushed& p) {
        return (p.mask & GL_ENABLE_BIT) && !(p.mask & GL_LIGHTING_BIT);
    });
}

bool popsNestedChange(const Call& call, const StreamContext& context) {
    return functionName(call) == "glPopAttrib" && context.attribStack.size() >= 2 &&
           context.attribStack.back().changedSince;
}

// glTexImage2D/glCopyTexImage2D's border argument and height, by argument position.
bool definesBorderedTexture(std::string_view name, const std::vector<double>& a, double& height) {
    if (name == "glTexImage1D" || name == "glCopyTexImage1D") {
        height = 1;
        return a[name == "glTexImage1D" ? 4 : 5] == 1;
    }
    if (name != "glTexImage2D" && name != "glCopyTexImage2D") return false;
    height = a[name == "glTexImage2D" ? 4 : 6];
    return a[name == "glTexImage2D" ? 5 : 7] == 1;
}

bool definesBorderWithoutRows(const Call& call, const StreamContext&) {
    double height = 0;
    return definesBorderedTexture(functionName(call), call.args, height) && height == 2;
}

bool queriesBorderedSize(const Call& call, const StreamContext& c) {
    const std::string_view name = functionName(call);
    if (!c.borderedTexture || !name.starts_with("glGetTexLevelParameter")) return false;
    const auto pname = static_cast<GLenum>(call.args[2]);
    return pname == GL_TEXTURE_WIDTH || pname == GL_TEXTURE_HEIGHT || pname == GL_TEXTURE_BORDER;
}

bool isPixelMapIToIAnySize(const Call& call, const StreamContext&) {
    const std::string_view name = functionName(call);
    if (!name.starts_with("glPixelMap") || static_cast<GLenum>(call.args[0]) != GL_PIXEL_MAP_I_TO_I) return false;
    const auto size = static_cast<std::int64_t>(call.args[1]);
    return size > 0 && (size & (size - 1)) != 0;
}

bool queriesPriorityAsInteger(const Call& call, const StreamContext&) {
    return functionName(call) == "glGetTexParameteriv" && static_cast<GLenum>(call.args[1]) == GL_TEXTURE_PRIORITY;
}

bool movesStencilAsBitmap(const Call& call, const StreamContext&) {
    const std::string_view name = functionName(call);
    const std::size_t format = name == "glReadPixels" ? 4 : name == "glDrawPixels" ? 2 : 0;
    return format && static_cast<GLenum>(call.args[format]) == GL_STENCIL_INDEX &&
           static_cast<GLenum>(call.args[format + 1]) == GL_BITMAP;
}

bool drawsIndexImage(const Call& call, const StreamContext&) {
    return functionName(call) == "glDrawPixels" && static_cast<GLenum>(call.args[2]) == GL_COLOR_INDEX;
}

// glGetTexLevelParameterfv that fails: a target, level or name GL rejects.
bool failsFloatLevelQuery(const Call& call, const StreamContext&) {
    if (functionName(call) != "glGetTexLevelParameterfv") return false;
    const auto target = static_cast<GLenum>(call.args[0]);
    const auto pname = static_cast<GLenum>(call.args[2]);
    constexpr GLenum kNames[] = {GL_TEXTURE_WIDTH,         GL_TEXTURE_HEIGHT,     GL_TEXTURE_BORDER,
                                 GL_TEXTURE_COMPONENTS,    GL_TEXTURE_RED_SIZE,   GL_TEXTURE_GREEN_SIZE,
                                 GL_TEXTURE_BLUE_SIZE,     GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
                                 GL_TEXTURE_INTENSITY_SIZE};
    return (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D) || call.args[1] < 0 || call.args[1] > 14 ||
           std::find(std::begin(kNames), std::end(kNames), pname) == std::end(kNames);
}

bool copiesBeyondTextureSize(const Call& call, const StreamContext&) {
    constexpr double kTextureSizeMax = 16384;  // llvmpipe's largest texture side
    return functionName(call) == "glCopyPixels" && (call.args[2] > kTextureSizeMax || call.args[3] > kTextureSizeMax);
}

bool copiesTextureWithBadInternalFormat(const Call& call, const StreamContext&) {
    const std::string_view name = functionName(call);
    if (name != "glCopyTexImage1D" && name != "glCopyTexImage2D") return false;
    const auto internal = static_cast<GLenum>(call.args[2]);
    // GL 1.1 leaves 1, 2, 3 and 4 out of glCopyTexImage's formats.
    constexpr GLenum kFormats[] = {GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, 0x8049,        GL_RGB,
                                   GL_RGBA,  GL_RGB8,      GL_RGBA8,           GL_LUMINANCE8, GL_ALPHA8};
    return std::find(std::begin(kFormats), std::end(kFormats), internal) == std::end(kFormats);
}

bool queriesLevelFormat(const Call& call, const StreamContext&) {
    return functionName(call).starts_with("glGetTexLevelParameter") &&
           static_cast<GLenum>(call.args[2]) == GL_TEXTURE_COMPONENTS;
}

bool drawsDepthWithUnflushedColor(const Call& call, const StreamContext& c) {
    const std::string_view name = functionName(call);
    const bool depth = (name == "glCopyPixels" && static_cast<GLenum>(call.args[4]) == GL_DEPTH) ||
                       (name == "glDrawPixels" && static_cast<GLenum>(call.args[2]) == GL_DEPTH_COMPONENT);
    return depth && c.colorSinceFlush;
}

// GL_POLYGON_OFFSET_POINT or _LINE on while GL_POLYGON_OFFSET_FILL is off: the enable or
// disable that would lead there (filled faces drawn then take the offset on OSMesa).
bool offsetsFilledByPointOrLine(const Call& call, const StreamContext& c) {
    const std::string_view name = functionName(call);
    if (c.insideBegin || (name != "glEnable" && name != "glDisable")) return false;
    const auto cap = static_cast<GLenum>(call.args[0]);
    if (name == "glEnable") return (cap == GL_POLYGON_OFFSET_POINT || cap == GL_POLYGON_OFFSET_LINE) && !c.offsetFill;
    return cap == GL_POLYGON_OFFSET_FILL && (c.offsetPoint || c.offsetLine);
}

int typeBytes(GLenum type) {
    return type == GL_UNSIGNED_BYTE || type == GL_BYTE ? 1 : type == GL_UNSIGNED_SHORT || type == GL_SHORT ? 2 : 4;
}

// A GL_COLOR_INDEX texture image whose indices OSMesa reads otherwise than GL: as one run of
// width x height values (rows padded, a row length other than the width, GL_BITMAP rows not of
// whole aligned bytes or skipped pixels), a float index truncated before a shift (or a negative
// fraction: odd data seeds give any floats), a signed index shifted right by more than 24.
bool readsIndexTextureImage(const Call& call, const StreamContext& c) {
    std::size_t widthAt = 0, formatAt = 0;
    if (!textureImageArguments(functionName(call), widthAt, formatAt)) return false;
    if (static_cast<GLenum>(call.args[formatAt]) != GL_COLOR_INDEX) return false;
    const auto type = static_cast<GLenum>(call.args[formatAt + 1]);
    if (c.indexShiftEverWide) return true;
    if (type == GL_FLOAT && (c.indexShiftEverSet || std::fmod(call.args.back(), 2.0) != 0.0)) return true;
    if (!c.unpackAlignment || !c.unpackRowLength || !c.unpackSkipPixels) return true;
    const double width = call.args[widthAt];
    const int alignment = *c.unpackAlignment;
    if (*c.unpackRowLength != 0 && *c.unpackRowLength != width) return true;
    if (type == GL_BITMAP) return *c.unpackSkipPixels != 0 || std::fmod(width, 8.0 * alignment) != 0.0;
    const int bytes = typeBytes(type);
    return bytes < alignment && std::fmod(width * bytes, alignment) != 0.0;
}

// glCopyTexImage2D/glCopyTexSubImage2D of more than one row while an image transfer may be on.
bool copiesRowsUnderTransfer(const Call& call, const StreamContext& c) {
    const std::string_view name = functionName(call);
    if (!c.imageTransferEverSet) return false;
    if (name == "glCopyTexImage2D") return call.args[6] > 1;
    return name == "glCopyTexSubImage2D" && call.args[7] > 1;
}

// A query (not glGetError) between a glBegin given while compiling a GL_COMPILE_AND_EXECUTE list
// and its glEnd.
bool queriesInsideExecutedListBegin(const Call& call, const StreamContext& c) {
    const std::string_view name = functionName(call);
    const bool query = (name.starts_with("glGet") && name != "glGetError") || name.starts_with("glIs");
    return query && c.insideBegin && c.beginFromExecutedList;
}

constexpr Departure kDepartures[] = {
    {"integer-query-of-matrix",
     "glGetIntegerv of a matrix: OSMesa maps entries like colours ([-1,1] to the integer range), the spec rounds them",
     isIntegerMatrixQuery},
    {"integer-query-out-of-range",
     "glGetIntegerv of a float state with no int value (NaN, beyond [-1,1] if normalized): OSMesa overflows, MyGL "
     "saturates",
     isIntegerQueryOutOfRange},
    {"boolean-kept-as-given",
     "glDepthMask/glEdgeFlag with a GLboolean other than 0 or 1: OSMesa answers the byte back (2), the spec GL_TRUE",
     isNonCanonicalBoolean},
    {"color3f-keeps-alpha",
     "glColor3f[v] after a glColor4* with alpha != 1 and no glFlush since: OSMesa keeps that alpha, the spec sets 1",
     isColor3fKeepingAlpha},
    {"line-loop-format-growth",
     "an attribute new to a GL_LINE_LOOP after its first vertex: OSMesa flushes the loop and loses its closing segment",
     growsLineLoopFormat},
    {"read-pixels-sum-overflow",
     "glReadPixels with x + width or y + height above INT_MAX: OSMesa's clipping overflows, it writes out of bounds",
     readPixelsSumOverflows},
    {"read-pixels-unknown-format",
     "glReadPixels with a format GL does not define: OSMesa reports GL_INVALID_OPERATION, the spec GL_INVALID_ENUM",
     readsUnknownFormat},
    {"light-under-enable-bit-push",
     "glEnable/glDisable(GL_LIGHTi) after a glPushAttrib(GL_ENABLE_BIT without GL_LIGHTING_BIT): OSMesa's pop keeps "
     "the light's new state",
     togglesLightUnderEnableBit},
    {"pop-after-nested-change",
     "glPopAttrib of a nested push after a state change: OSMesa resets its changed-groups mask to the push's, so the "
     "outer pop skips groups changed inside",
     popsNestedChange},
    {"texture-border-without-rows",
     "glTexImage2D/glCopyTexImage2D with border 1 and height 2: OSMesa strips the border from the width only (a w-2 x "
     "2 image), the spec's image has no rows",
     definesBorderWithoutRows},
    {"texture-border-stripped",
     "glGetTexLevelParameter of GL_TEXTURE_WIDTH/HEIGHT/BORDER after a bordered image: OSMesa stores it stripped "
     "(width - 2, border 0), the spec counts the border",
     queriesBorderedSize},
    {"pixel-map-i-to-i-any-size",
     "glPixelMap(GL_PIXEL_MAP_I_TO_I) with a size not a power of two: OSMesa takes it, the spec gives GL_INVALID_VALUE",
     isPixelMapIToIAnySize},
    {"stencil-as-bitmap",
     "glReadPixels/glDrawPixels(GL_STENCIL_INDEX, GL_BITMAP): OSMesa never returns (glReadPixels loops printing "
     "'Unsupported format/type'); the spec moves bits",
     movesStencilAsBitmap},
    {"index-image",
     "glDrawPixels(GL_COLOR_INDEX): OSMesa reads past its own image buffer (ASan, seed 71: 11 x 4 bytes) and as "
     "GL_BITMAP draws memory it never wrote (seed 209)",
     drawsIndexImage},
    {"failed-level-query-writes",
     "glGetTexLevelParameterfv with a bad target, level or name: OSMesa records the error and still writes its "
     "uninitialized int (0) to params",
     failsFloatLevelQuery},
    {"copy-pixels-beyond-texture-size",
     "glCopyPixels wider or taller than 16384 not done as a blit: OSMesa draws its rectangle as zeros (its texture "
     "cannot hold the copy); MyGL copies nothing",
     copiesBeyondTextureSize},
    {"copy-texture-bad-internal-format",
     "glCopyTexImage1D/2D with an internal format GL 1.1 does not take (1-4 too): OSMesa gives GL_INVALID_ENUM, GL 1.1 "
     "GL_INVALID_VALUE",
     copiesTextureWithBadInternalFormat},
    {"depth-image-unflushed-color",
     "glCopyPixels(GL_DEPTH)/glDrawPixels(GL_DEPTH_COMPONENT) after a glColor outside glBegin/glEnd and no glFlush "
     "since: OSMesa colours the fragments with ctx->Current before that glColor (not flushed: _mesa_CopyPixels only "
     "flushes vertices)",
     drawsDepthWithUnflushedColor},
    {"undefined-level-format",
     "glGetTexLevelParameter(GL_TEXTURE_COMPONENTS) of a level with no image: OSMesa answers GL_RGBA (GL 3's initial "
     "value), GL 1.1's is 1",
     queriesLevelFormat},
    {"offset-point-line-on-fill",
     "GL_POLYGON_OFFSET_POINT or _LINE on with _FILL off: OSMesa sends filled faces through the draw module, whose "
     "offset stage offsets every triangle; the spec offsets them only under GL_POLYGON_OFFSET_FILL",
     offsetsFilledByPointOrLine},
    {"index-texture-image",
     "a GL_COLOR_INDEX texture image: OSMesa reads its indices as one run of width x height values (rows unpadded), "
     "truncates float indices before the shift and shifts them as 32-bit unsigned",
     readsIndexTextureImage},
    {"copy-texture-rows-under-transfer",
     "glCopyTexImage2D/glCopyTexSubImage2D of several rows under a pixel transfer: OSMesa's fallback copy reads the "
     "rows with a negative stride from its buffer's first, so all but the top row come from memory before it",
     copiesRowsUnderTransfer},
    {"texture-priority-as-integer",
     "glGetTexParameteriv(GL_TEXTURE_PRIORITY): OSMesa maps [0, 1] to [0, INT_MAX], the spec rounds",
     queriesPriorityAsInteger},
    {"query-inside-executed-list-begin",
     "glGet*/glIs* between a glBegin compiled under GL_COMPILE_AND_EXECUTE and its glEnd: OSMesa answers as outside "
     "glBegin/glEnd (it plays the list's primitives later), the spec gives GL_INVALID_OPERATION",
     queriesInsideExecutedListBegin},
};

}  // namespace

void StreamContext::update(const Call& call) {
    const std::string_view name = functionName(call);
    const std::array<bool*, 6> flags = {&colorBeyondUnit,    &normalBeyondUnit,   &texCoordBeyondInt,
                                        &lineWidthBeyondInt, &pointSizeBeyondInt, &alphaNotOneSinceFlush};
    const bool query = name == "glGetError" || name.starts_with("glGet") || name == "glIsEnabled";
    if (!attribStack.empty() && !query && name != "glPushAttrib" && name != "glPopAttrib")
        attribStack.back().changedSince = true;
    if (name == "glPushAttrib" && !insideBegin && attribStack.size() < 16) {
        Pushed pushed{static_cast<GLbitfield>(call.args[0]), {}};
        for (std::size_t i = 0; i < flags.size(); ++i) pushed.flags[i] = *flags[i];
        attribStack.push_back(pushed);
    } else if (name == "glPopAttrib" && !insideBegin && !attribStack.empty()) {
        for (std::size_t i = 0; i < flags.size(); ++i) *flags[i] = *flags[i] || attribStack.back().flags[i];
        attribStack.pop_back();
        offsetFill = false, offsetLine = offsetPoint = true;
    } else if ((name == "glEnable" || name == "glDisable") && !insideBegin) {
        const bool on = name == "glEnable";
        switch (static_cast<GLenum>(call.args[0])) {
        case GL_POLYGON_OFFSET_FILL: offsetFill = on; break;
        case GL_POLYGON_OFFSET_LINE: offsetLine = on; break;
        case GL_POLYGON_OFFSET_POINT: offsetPoint = on; break;
        default: break;
        }
    } else if (name == "glNewList") {
        const bool listMode = call.args[1] == GL_COMPILE || call.args[1] == GL_COMPILE_AND_EXECUTE;
        if (insideBegin || listOpen || call.args[0] == 0 || !listMode) return;  // an error: no list opens
        listOpen = true;
        compilingAndExecuting = call.args[1] == GL_COMPILE_AND_EXECUTE;
    } else if (name == "glEndList") {
        listOpen = compilingAndExecuting = false;
    } else if (name == "glBegin") {
        if (insideBegin || call.args[0] > GL_POLYGON) return;  // an error: nothing begins
        insideBegin = true;
        beginFromExecutedList = compilingAndExecuting;
        mode = static_cast<GLenum>(call.args[0]);
        verticesInBlock = 0;
        inBlock = atFirstVertex = {};
    } else if (name == "glEnd") {
        insideBegin = beginFromExecutedList = false;
    } else if (double height = 0; definesBorderedTexture(name, call.args, height)) {
        borderedTexture = true;
    } else if (name == "glPixelStorei" || name == "glPixelStoref") {
        std::optional<int>* unpackMode = nullptr;
        switch (static_cast<GLenum>(call.args[0])) {
        case GL_UNPACK_ALIGNMENT: unpackMode = &unpackAlignment; break;
        case GL_UNPACK_ROW_LENGTH: unpackMode = &unpackRowLength; break;
        case GL_UNPACK_SKIP_PIXELS: unpackMode = &unpackSkipPixels; break;
        default: return;
        }
        const double v = call.args[1];
        const bool valid = unpackMode == &unpackAlignment ? (v == 1 || v == 2 || v == 4 || v == 8) : v >= 0;
        if (name == "glPixelStoref" || insideBegin) {
            *unpackMode = std::nullopt;  // a float rounds (or a call inside glBegin fails): taken as unknown
        } else if (valid && v < kIntLimit) {
            *unpackMode = static_cast<int>(v);
        }
    } else if (name == "glPopClientAttrib") {
        unpackAlignment = unpackRowLength = unpackSkipPixels = std::nullopt;
    } else if (name == "glPixelTransferi" || name == "glPixelTransferf") {
        const auto pname = static_cast<GLenum>(call.args[0]);
        const double v = call.args[1];
        if (pname == GL_INDEX_SHIFT) {
            indexShiftEverSet |= v != 0;
            indexShiftEverWide |= !(std::abs(v) <= 24);
        }
        const bool scale =
            pname == GL_RED_SCALE || pname == GL_GREEN_SCALE || pname == GL_BLUE_SCALE || pname == GL_ALPHA_SCALE;
        const bool bias =
            pname == GL_RED_BIAS || pname == GL_GREEN_BIAS || pname == GL_BLUE_BIAS || pname == GL_ALPHA_BIAS;
        colorTransferEverSet |= (scale && v != 1) || (bias && v != 0) || (pname == GL_MAP_COLOR && v != 0);
        imageTransferEverSet |=
            colorTransferEverSet || ((pname == GL_INDEX_SHIFT || pname == GL_INDEX_OFFSET) && v != 0);
    } else if (name == "glFlush" || name == "glFinish") {
        alphaNotOneSinceFlush = false;
        colorSinceFlush = false;
    } else if (name == "glLineWidth" || name == "glPointSize") {
        if (insideBegin || call.args[0] <= 0) return;  // an error: the state stays
        (name == "glLineWidth" ? lineWidthBeyondInt : pointSizeBeyondInt) = !(call.args[0] < kIntLimit);
    } else if (name.starts_with("glColor")) {
        colorSinceFlush |= !insideBegin;
        colorBeyondUnit = anyBeyond(name, call.args, 1.0, true);
        if (components(name, "glColor") == 4 && !setsAlphaOne(name, call.args[3])) alphaNotOneSinceFlush = true;
        if (insideBegin) inBlock.colorSize = std::max(inBlock.colorSize, components(name, "glColor"));
    } else if (name.starts_with("glNormal")) {
        normalBeyondUnit = anyBeyond(name, call.args, 1.0, true);
        inBlock.normal |= insideBegin;
    } else if (name.starts_with("glTexCoord")) {
        texCoordBeyondInt = anyBeyond(name, call.args, kIntLimit, false);
        inBlock.texCoord |= insideBegin;
    } else if (insideBegin && name.starts_with("glEdgeFlag")) {
        inBlock.edgeFlag = true;
    } else if (insideBegin && name.starts_with("glVertex")) {
        if (verticesInBlock++ > 0) return;
        inBlock.vertexSize = components(name, "glVertex");
        atFirstVertex = inBlock;
    }
}

bool textureImageArguments(std::string_view name, std::size_t& width, std::size_t& format) {
    if (name == "glTexImage1D") return width = 3, format = 5, true;
    if (name == "glTexImage2D") return width = 3, format = 6, true;
    if (name == "glTexSubImage1D") return width = 3, format = 4, true;
    if (name == "glTexSubImage2D") return width = 4, format = 6, true;
    return false;
}

std::span<const Departure> referenceDepartures() { return kDepartures; }

const Departure* departureFor(const Call& call, const StreamContext& context) {
    for (const Departure& d : kDepartures) {
        if (d.matches(call, context)) return &d;
    }
    return nullptr;
}

}  // namespace fuzz
