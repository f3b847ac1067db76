#include "generator.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "pixel_feature_calls.h"
#include "random_source.h"
#include "reference_departures.h"

namespace fuzz {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kIntMin = std::numeric_limits<GLint>::min();
constexpr double kIntMax = std::numeric_limits<GLint>::max();

constexpr std::size_t kReadPixelsBytesMax = std::size_t{64} << 20;
constexpr GLenum kRescaleNormal = 0x803A;  // GL 1.2, not in the GL 1.1 header

// The capabilities glEnable may toggle in a stream: the two MyGL draws with, and those whose
// default state leaves every pixel as it was (MyGL accepts them and draws nothing different).
constexpr GLenum kDrawnCapabilities[] = {GL_CULL_FACE, GL_DEPTH_TEST};
constexpr GLenum kHarmlessCapabilities[] = {GL_DITHER,         GL_NORMALIZE,  GL_LIGHT0,    GL_LIGHT7,
                                            GL_COLOR_MATERIAL, GL_ALPHA_TEST, GL_BLEND,     GL_SCISSOR_TEST,
                                            GL_STENCIL_TEST,   GL_TEXTURE_1D, GL_TEXTURE_2D};
// Not a valid value for any enum parameter the fuzzer passes them to.
constexpr GLenum kInvalidEnums[] = {0x1234, 0xFFFF, 0xFFFFFFFF, 0x7FFF0000, GL_RGBA};

constexpr GLenum kQueryNames[] = {
    GL_VIEWPORT,
    GL_MODELVIEW_MATRIX,
    GL_PROJECTION_MATRIX,
    GL_TEXTURE_MATRIX,
    GL_MATRIX_MODE,
    GL_MODELVIEW_STACK_DEPTH,
    GL_PROJECTION_STACK_DEPTH,
    GL_TEXTURE_STACK_DEPTH,
    GL_MAX_MODELVIEW_STACK_DEPTH,
    GL_MAX_PROJECTION_STACK_DEPTH,
    GL_MAX_TEXTURE_STACK_DEPTH,
    GL_MAX_VIEWPORT_DIMS,
    GL_CULL_FACE,
    GL_DEPTH_TEST,
    GL_CULL_FACE_MODE,
    GL_FRONT_FACE,
    GL_DEPTH_FUNC,
    GL_DEPTH_WRITEMASK,
    GL_SHADE_MODEL,
    GL_POLYGON_MODE,
    GL_LINE_WIDTH,
    GL_POINT_SIZE,
    GL_DEPTH_RANGE,
    GL_COLOR_CLEAR_VALUE,
    GL_DEPTH_CLEAR_VALUE,
    GL_CURRENT_COLOR,
    GL_CURRENT_NORMAL,
    GL_CURRENT_TEXTURE_COORDS,
    GL_EDGE_FLAG,
    GL_RED_BITS,
    GL_GREEN_BITS,
    GL_BLUE_BITS,
    GL_ALPHA_BITS,
    GL_DEPTH_BITS,
    GL_STENCIL_BITS,
    GL_SUBPIXEL_BITS,
    GL_PACK_ALIGNMENT,
    GL_UNPACK_ALIGNMENT,
    GL_DOUBLEBUFFER,
};

struct Point {
    double x, y, z;
};

enum class Shape { Scatter, Circle, ZigZag, Grid, Sliver };

class Generator {
public:
    Generator(std::uint64_t seed, const GeneratorOptions& options, AvoidedCounts& avoided)
        : random_(seed), attribRandom_(seed ^ 0xA77B5EEDu), featureRandom_(seed ^ 0xFEA7u), avoided_(avoided) {
        const bool large = random_.chance(0.25);
        stream_.width = static_cast<int>(random_.integer(1, large ? options.sizeMax : std::min(64, options.sizeMax)));
        stream_.height = static_cast<int>(random_.integer(1, large ? options.sizeMax : std::min(64, options.sizeMax)));
        badness_ = random_.pick({0.0, 0.0, 0.0, 0.02, 0.02, 0.15});
        invalidEnumRate_ = badness_ > 0 ? 0.1 : 0.01;
        bigDrawLeft_ = random_.chance(0.03);
        pixelFeatures_.emplace(seed, stream_.width, stream_.height, badness_, invalidEnumRate_);
    }

    Stream generate() {
        if (random_.chance(0.7)) setProjection();
        const auto episodes = random_.integer(3, 40);
        for (std::int64_t i = 0; i < episodes; ++i) {
            episode();
            attribStackCall();
            featureCalls();
            pixelFeatures_->between([this](Call call) { emit(std::move(call)); });
            if (random_.chance(0.6)) emit("glGetError");
        }
        emit("glGetError");
        return std::move(stream_);
    }

private:
    // --- emitting calls -------------------------------------------------------------------------
    void emit(std::string_view name, std::vector<double> args = {}) { emit(makeCall(name, std::move(args))); }
    void emit(Call call) {
        if (const Departure* d = departureFor(call, context_)) {
            ++avoided_[d->name];
            return;
        }
        context_.update(call);
        stream_.calls.push_back(std::move(call));
    }

    // --- values ---------------------------------------------------------------------------------
    // `value` as a GL type given by its suffix (f, d, s, i, b, ub, us, ui), or, at the stream's
    // badness rate, a bad value of that type.
    double as(std::string_view type, double value) {
        if (random_.chance(badness_)) return bad(type);
        if (type == "f") return static_cast<float>(value);
        if (type == "d") return value;
        const double rounded = std::round(value);
        if (type == "s") return std::clamp(rounded, -32768.0, 32767.0);
        if (type == "b") return std::clamp(rounded, -128.0, 127.0);
        if (type == "ub") return std::clamp(rounded, 0.0, 255.0);
        if (type == "us") return std::clamp(rounded, 0.0, 65535.0);
        if (type == "ui") return std::clamp(rounded, 0.0, 4294967295.0);
        return std::clamp(rounded, kIntMin, kIntMax);
    }
    double bad(std::string_view type) {
        if (type == "f")
            return static_cast<float>(
                random_.pick({kNaN, kInf, -kInf, 1e30, -1e30, 3.4e38, -3.4e38, 1e-40, -1e-45, -0.0, 1e-30}));
        if (type == "d")
            return random_.pick({kNaN, kInf, -kInf, 1e30, -1e30, 1e300, -1e300, 5e-324, 1e-310, -0.0, 1e-30});
        if (type == "s") return random_.pick({-32768.0, 32767.0});
        if (type == "b") return random_.pick({-128.0, 127.0});
        if (type == "ub") return 255.0;
        if (type == "us") return 65535.0;
        if (type == "ui") return 4294967295.0;
        return random_.pick({kIntMin, kIntMax, 1073741824.0});
    }
    // Any value of an integer colour/normal type, or a float in a range around [0, 1].
    double anyOf(std::string_view type, double low, double high) {
        if (type == "b") return static_cast<double>(random_.integer(-128, 127));
        if (type == "ub") return static_cast<double>(random_.integer(0, 255));
        if (type == "s") return static_cast<double>(random_.integer(-32768, 32767));
        if (type == "us") return static_cast<double>(random_.integer(0, 65535));
        if (type == "i") return static_cast<double>(random_.integer(-2147483648LL, 2147483647LL));
        if (type == "ui") return static_cast<double>(random_.integer(0, 4294967295LL));
        return as(type, random_.chance(0.7) ? random_.uniform(0, 1) : random_.uniform(low, high));
    }
    GLenum oneOf(std::initializer_list<GLenum> valid) {
        if (random_.chance(invalidEnumRate_)) return invalidEnum();
        return valid.begin()[random_.integer(0, static_cast<std::int64_t>(valid.size()) - 1)];
    }
    template <std::size_t N>
    GLenum oneOf(const GLenum (&valid)[N]) {
        if (random_.chance(invalidEnumRate_)) return invalidEnum();
        return valid[random_.integer(0, N - 1)];
    }
    GLenum invalidEnum() { return kInvalidEnums[random_.integer(0, std::size(kInvalidEnums) - 1)]; }
    std::string_view floatType() { return random_.chance(0.5) ? "f" : "d"; }

    // --- space ----------------------------------------------------------------------------------
    // Object coordinates for (u, v, w) in about [-1, 1]: unit space, or window pixels under a
    // glOrtho(0, width, 0, height) projection.
    Point place(double u, double v, double w) const {
        if (!pixelSpace_) return {1.2 * u, 1.2 * v, 1.2 * w};
        return {(u * 0.6 + 0.5) * stream_.width, (v * 0.6 + 0.5) * stream_.height, 0.9 * w};
    }

    Point shapePoint(Shape shape, std::int64_t i, std::int64_t n, const Point& centre, double size) {
        const double jitter = random_.uniform(-0.02, 0.02) * size;
        switch (shape) {
        case Shape::Circle: {
            const double angle = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
            const double r = i == 0 && random_.chance(0.5) ? 0 : size * random_.uniform(0.7, 1.0);
            return {centre.x + r * std::cos(angle), centre.y + r * std::sin(angle), centre.z + jitter};
        }
        case Shape::ZigZag: {
            const double t = static_cast<double>(i / 2) / static_cast<double>(std::max<std::int64_t>(1, n / 2 - 1));
            return {-1 + 2 * t + jitter, centre.y + (i % 2 ? size : -size) * 0.5 + jitter, centre.z + t * 0.5 - 0.25};
        }
        case Shape::Grid: {
            const auto cells = static_cast<std::int64_t>(std::ceil(std::sqrt(static_cast<double>(n / 4 + 1))));
            const std::int64_t cell = i / 4, corner = i % 4;
            const double step = 2.0 / static_cast<double>(cells);
            const double cx = -1 + step * static_cast<double>(cell % cells),
                         cy = -1 + step * static_cast<double>(cell / cells);
            return {cx + (corner == 1 || corner == 2 ? step : 0) + jitter, cy + (corner >= 2 ? step : 0) + jitter,
                    centre.z + 0.3 * cx};
        }
        case Shape::Sliver: {
            const double t = random_.uniform(-1, 1);
            return {centre.x + t * size, centre.y + t * size * 0.3 + random_.uniform(-1e-3, 1e-3), centre.z + t * 0.2};
        }
        case Shape::Scatter: break;
        }
        return {centre.x + random_.uniform(-1, 1) * size, centre.y + random_.uniform(-1, 1) * size,
                centre.z + random_.uniform(-1, 1) * size};
    }

    // --- episodes -------------------------------------------------------------------------------
    void episode() {
        const auto roll = random_.integer(0, 99);
        if (roll < 36) return draw();
        if (roll < 54) {
            for (auto n = random_.integer(1, 4); n > 0; --n) emit(stateCall());
            return;
        }
        if (roll < 64) {
            for (auto n = random_.integer(1, 5); n > 0; --n) emit(matrixCall());
            return;
        }
        if (roll < 71) return setProjection();
        if (roll < 82) return emit(queryCall());
        if (roll < 87) return emit(readPixelsCall());
        if (roll < 92) return clear();
        if (roll < 96) return emit(rectCall());
        if (roll < 98) return stackAbuse();
        emit(random_.chance(0.5) ? "glFlush" : "glFinish");
    }

    void setProjection() {
        emit("glMatrixMode", {GL_PROJECTION});
        emit("glLoadIdentity");
        const auto kind = random_.integer(0, 3);
        pixelSpace_ = kind == 2;
        if (kind == 0) {
            emit("glOrtho",
                 {as("d", -random_.uniform(1, 2)), as("d", random_.uniform(1, 2)), as("d", -random_.uniform(1, 2)),
                  as("d", random_.uniform(1, 2)), as("d", -random_.uniform(1, 3)), as("d", random_.uniform(1, 3))});
        } else if (kind == 1) {
            const double n = random_.uniform(0.3, 2.5);
            emit("glFrustum", {as("d", -n * random_.uniform(0.3, 1)), as("d", n * random_.uniform(0.3, 1)),
                               as("d", -n * random_.uniform(0.3, 1)), as("d", n * random_.uniform(0.3, 1)), as("d", n),
                               as("d", random_.uniform(3.5, 20))});
        } else if (kind == 2) {
            emit("glOrtho", {0, static_cast<double>(stream_.width), 0, static_cast<double>(stream_.height), -1, 1});
        }
        emit("glMatrixMode", {GL_MODELVIEW});
        emit("glLoadIdentity");
        if (kind == 1) emit("glTranslatef", {0, 0, as("f", -random_.uniform(2.0, 3.5))});
        if (!pixelSpace_ && random_.chance(0.6)) emit(rotateCall());
    }

    Call rotateCall() {
        const auto t = floatType();
        return makeCall(t == "f" ? "glRotatef" : "glRotated",
                        {as(t, random_.uniform(-180, 180)), as(t, random_.uniform(-1, 1)),
                         as(t, random_.uniform(-1, 1)), as(t, random_.uniform(-1, 1))});
    }

    GLenum drawMode() {
        // Not 0xA-0xE: OSMesa is a GL 4.5 context, where those are the adjacency and patch modes.
        if (random_.chance(invalidEnumRate_ / 2)) return random_.pick<GLenum>({0xF, 0xFFFF, GL_FRONT});
        return static_cast<GLenum>(random_.integer(GL_POINTS, GL_POLYGON));
    }

    std::int64_t vertexCount(GLenum mode) {
        switch (mode) {
        case GL_POINTS: return random_.integer(1, 20);
        case GL_QUADS: return random_.integer(3, 41);
        case GL_POLYGON: return random_.integer(2, 12);
        default: return random_.integer(1, 30);
        }
    }

    Shape naturalShape(GLenum mode) {
        if (random_.chance(0.3)) return random_.chance(0.8) ? Shape::Scatter : Shape::Sliver;
        switch (mode) {
        case GL_TRIANGLE_FAN:
        case GL_POLYGON:
        case GL_LINE_LOOP: return Shape::Circle;
        case GL_TRIANGLE_STRIP:
        case GL_QUAD_STRIP:
        case GL_LINE_STRIP: return Shape::ZigZag;
        case GL_QUADS:
        case GL_TRIANGLES: return Shape::Grid;
        default: return Shape::Scatter;
        }
    }

    // How a glBegin/glEnd block sends its per-vertex attributes.
    struct VertexPlan {
        double colorRate = 0, normalRate = 0, texCoordRate = 0, edgeFlagRate = 0;
        std::string colorType = "f", normalType = "f", texCoordType = "f", vertexType = "f";
        int colorSize = 3, vertexSize = 3;
        bool mixTypes = false, vectorForms = false;
        double strangeW = 0;  // rate of w = 0, negative or close to 0
    };

    VertexPlan vertexPlan(bool big) {
        VertexPlan p;
        p.colorRate = random_.pick({0.0, 1.0, 1.0, 0.5});
        p.colorType = random_.pick<std::string>({"b", "ub", "s", "us", "i", "ui", "f", "d"});
        p.colorSize = random_.chance(0.5) ? 3 : 4;
        p.vertexSize = static_cast<int>(random_.integer(2, 4));
        if (big) return p;
        p.normalRate = random_.pick({0.0, 0.0, 0.5, 1.0});
        p.texCoordRate = random_.pick({0.0, 0.0, 0.5});
        p.edgeFlagRate = random_.pick({0.0, 0.0, 0.3});
        p.normalType = random_.pick<std::string>({"b", "s", "i", "f", "d"});
        p.texCoordType = random_.pick<std::string>({"s", "i", "f", "d"});
        p.vertexType = random_.pick<std::string>({"s", "i", "f", "d", "f", "d"});
        p.mixTypes = random_.chance(0.2);
        p.vectorForms = random_.chance(0.4);
        p.strangeW = badness_ > 0 ? random_.pick({0.0, 0.1, 0.5}) : 0.0;
        return p;
    }

    // "glColor4ubv" from its parts; the v form at the plan's rate.
    std::string entryName(const char* base, int size, const std::string& type, bool vectorForm) {
        return base + (size ? std::to_string(size) : std::string()) + type + (vectorForm ? "v" : "");
    }

    void attributes(const VertexPlan& p) {
        const auto typeOf = [&](const std::string& planned, std::initializer_list<std::string> all) {
            return p.mixTypes ? random_.pick(all) : planned;
        };
        if (random_.chance(p.colorRate)) {
            const std::string t = typeOf(p.colorType, {"b", "ub", "s", "us", "i", "ui", "f", "d"});
            const int size = p.mixTypes ? (random_.chance(0.5) ? 3 : 4) : p.colorSize;
            std::vector<double> c;
            for (int i = 0; i < size; ++i) c.push_back(anyOf(t, -0.5, 1.5));
            emit(entryName("glColor", size, t, p.vectorForms && random_.chance(0.5)), c);
        }
        if (random_.chance(p.normalRate)) {
            const std::string t = typeOf(p.normalType, {"b", "s", "i", "f", "d"});
            emit(entryName("glNormal", 3, t, p.vectorForms && random_.chance(0.5)),
                 {anyOf(t, -1.5, 1.5), anyOf(t, -1.5, 1.5), anyOf(t, -1.5, 1.5)});
        }
        if (random_.chance(p.texCoordRate)) {
            const std::string t = typeOf(p.texCoordType, {"s", "i", "f", "d"});
            emit(entryName("glTexCoord", 2, t, p.vectorForms && random_.chance(0.5)),
                 {as(t, random_.uniform(-4, 4)), as(t, random_.uniform(-4, 4))});
        }
        if (random_.chance(p.edgeFlagRate)) {
            emit(random_.chance(0.5) ? "glEdgeFlag" : "glEdgeFlagv", {static_cast<double>(random_.integer(0, 1))});
        }
    }

    void vertex(const VertexPlan& p, const Point& object) {
        const int size = p.mixTypes ? static_cast<int>(random_.integer(2, 4)) : p.vertexSize;
        const std::string t = p.mixTypes ? random_.pick<std::string>({"s", "i", "f", "d"}) : p.vertexType;
        double w = 1;
        if (size == 4) {
            w = random_.uniform(0.5, 2);
            if (random_.chance(p.strangeW)) w = random_.pick({0.0, -1.0, -0.5, 1e-7, -1e-7, 1e-4, 1e-30});
        }
        std::vector<double> v{as(t, object.x * w), as(t, object.y * w)};
        if (size > 2) v.push_back(as(t, object.z * w));
        if (size > 3) v.push_back(as(t, w));
        emit(entryName("glVertex", size, t, p.vectorForms && random_.chance(0.5)), v);
    }

    void draw() {
        const bool big = bigDrawLeft_ && random_.chance(0.3);
        if (big) bigDrawLeft_ = false;
        const GLenum mode = big ? static_cast<GLenum>(random_.integer(GL_POINTS, GL_POLYGON)) : drawMode();
        const auto n = big ? random_.integer(10000, 100000) : vertexCount(mode);
        const VertexPlan plan = vertexPlan(big);
        const Shape shape = naturalShape(mode);
        const Point centre{random_.uniform(-0.5, 0.5), random_.uniform(-0.5, 0.5), random_.uniform(-0.5, 0.5)};
        const double size = random_.pick({0.02, 0.3, 0.8, 1.5});
        emit("glBegin", {static_cast<double>(mode)});
        for (std::int64_t i = 0; i < n; ++i) {
            attributes(plan);
            const Point p = shapePoint(shape, i, n, centre, size);
            vertex(plan, place(p.x, p.y, p.z));
            if (!big && random_.chance(badness_ / 4)) emit(illegalInsideBegin());
        }
        if (random_.chance(0.3)) attributes(plan);  // attributes after the last vertex
        emit("glEnd");
    }

    Call illegalInsideBegin() {
        switch (random_.integer(0, 6)) {
        case 0: return stateCall();
        case 1: return matrixCall();
        case 2: return queryCall();
        case 3: return readPixelsCall();
        case 4: return rectCall();
        case 5: return makeCall("glBegin", {static_cast<double>(drawMode())});
        default: return makeCall("glGetError");
        }
    }

    Call stateCall() {
        const auto flag = [&] { return static_cast<double>(random_.chance(0.9) ? random_.integer(0, 1) : 2); };
        switch (random_.integer(0, 15)) {
        case 0:
        case 1: {
            const GLenum cap = random_.chance(0.7) ? oneOf(kDrawnCapabilities) : oneOf(kHarmlessCapabilities);
            return makeCall(random_.chance(0.6) ? "glEnable" : "glDisable", {static_cast<double>(cap)});
        }
        case 2: return makeCall("glCullFace", {static_cast<double>(oneOf({GL_FRONT, GL_BACK, GL_FRONT_AND_BACK}))});
        case 3: return makeCall("glFrontFace", {static_cast<double>(oneOf({GL_CW, GL_CCW}))});
        case 4:
            return makeCall("glDepthFunc",
                            {static_cast<double>(oneOf({GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL,
                                                        GL_GEQUAL, GL_ALWAYS}))});
        case 5: return makeCall("glDepthMask", {flag()});
        case 6: return makeCall("glShadeModel", {static_cast<double>(oneOf({GL_FLAT, GL_SMOOTH}))});
        case 7:
            return makeCall("glPolygonMode", {static_cast<double>(oneOf({GL_FRONT, GL_BACK, GL_FRONT_AND_BACK})),
                                              static_cast<double>(oneOf({GL_POINT, GL_LINE, GL_FILL}))});
        case 8:
            return makeCall("glLineWidth", {as("f", random_.chance(0.5) ? static_cast<double>(random_.integer(1, 4))
                                                                        : random_.uniform(0.3, 6))});
        case 9:
            return makeCall("glPointSize", {as("f", random_.chance(0.5) ? static_cast<double>(random_.integer(1, 5))
                                                                        : random_.uniform(0.3, 8))});
        case 10: return viewportCall();
        case 11: return depthRangeCall();
        case 12:
            return makeCall("glPixelStorei", {static_cast<double>(oneOf({GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT})),
                                              random_.chance(0.9 - badness_) ? random_.pick({1.0, 2.0, 4.0, 8.0})
                                                                             : random_.pick({0.0, 3.0, -1.0, 16.0})});
        case 13:
            return makeCall("glHint",
                            {static_cast<double>(oneOf({GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT,
                                                        GL_LINE_SMOOTH_HINT, GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT})),
                             static_cast<double>(oneOf({GL_DONT_CARE, GL_FASTEST, GL_NICEST}))});
        case 14: return makeCall("glEdgeFlag", {flag()});
        default:
            return makeCall("glClearColor", {anyOf("f", -0.5, 1.5), anyOf("f", -0.5, 1.5), anyOf("f", -0.5, 1.5),
                                             anyOf("f", -0.5, 1.5)});
        }
    }

    Call viewportCall() {
        const double w = stream_.width, h = stream_.height;
        if (random_.chance(badness_ > 0 ? 0.3 : 0.02)) {  // extreme
            return makeCall("glViewport", {random_.pick({kIntMin, kIntMax, -100000.0, 100000.0, 0.0}),
                                           random_.pick({kIntMin, kIntMax, -100000.0, 0.0}),
                                           random_.pick({-1.0, 0.0, kIntMax, 16384.0, 16385.0, 100000.0}),
                                           random_.pick({-1.0, 0.0, kIntMax, 16384.0, 100000.0})});
        }
        if (random_.chance(0.4)) return makeCall("glViewport", {0, 0, w, h});
        return makeCall("glViewport",
                        {std::round(random_.uniform(-0.5, 0.8) * w), std::round(random_.uniform(-0.5, 0.8) * h),
                         std::round(random_.uniform(0, 1.5) * w), std::round(random_.uniform(0, 1.5) * h)});
    }

    Call depthRangeCall() {
        if (random_.chance(0.3)) return makeCall("glDepthRange", {random_.pick({0.0, 1.0}), random_.pick({0.0, 1.0})});
        return makeCall("glDepthRange", {as("d", random_.uniform(-0.2, 1.2)), as("d", random_.uniform(-0.2, 1.2))});
    }

    Call matrixCall() {
        const auto t = floatType();
        const bool f = t == "f";
        switch (random_.integer(0, 11)) {
        case 0:
            return makeCall("glMatrixMode",
                            {static_cast<double>(oneOf({GL_MODELVIEW, GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE}))});
        case 1: return makeCall("glPushMatrix");
        case 2: return makeCall("glPopMatrix");
        case 3: return makeCall("glLoadIdentity");
        case 4:
            return makeCall(f ? "glTranslatef" : "glTranslated",
                            {as(t, random_.uniform(-0.5, 0.5)), as(t, random_.uniform(-0.5, 0.5)),
                             as(t, random_.uniform(-0.5, 0.5))});
        case 5: return rotateCall();
        case 6:
            return makeCall(f ? "glScalef" : "glScaled",
                            {as(t, random_.uniform(-1.5, 1.5)), as(t, random_.uniform(-1.5, 1.5)),
                             as(t, random_.uniform(-1.5, 1.5))});
        case 7:
        case 8: {
            std::vector<double> m(16);
            for (int i = 0; i < 16; ++i)
                m[i] = as(t, (i % 5 == 0 ? 1.0 : 0.0) + random_.uniform(-0.3, 0.3) * (random_.chance(0.5) ? 1 : 0));
            const bool load = random_.chance(0.4);
            return makeCall(std::string(load ? "glLoadMatrix" : "glMultMatrix") + std::string(t), m);
        }
        case 9: {
            const double n = random_.uniform(0.1, 2);
            return makeCall("glFrustum", {as("d", -n), as("d", n), as("d", -n), as("d", n),
                                          as("d", random_.chance(0.9) ? n : random_.pick({0.0, -1.0})),
                                          as("d", random_.uniform(2, 50))});
        }
        case 10:
            return makeCall("glOrtho", {as("d", -random_.uniform(0.5, 3)), as("d", random_.uniform(0.5, 3)),
                                        as("d", -random_.uniform(0.5, 3)), as("d", random_.uniform(0.5, 3)),
                                        as("d", -random_.uniform(0.5, 3)),
                                        as("d", random_.chance(0.95) ? random_.uniform(0.5, 3) : 0.0)});
        default: return makeCall(random_.chance(0.5) ? "glPushMatrix" : "glPopMatrix");
        }
    }

    Call queryCall() {
        switch (random_.integer(0, 9)) {
        case 0: return makeCall("glGetError");
        case 1: {
            const GLenum cap = random_.chance(0.6) ? oneOf(kDrawnCapabilities) : oneOf(kHarmlessCapabilities);
            return makeCall("glIsEnabled", {static_cast<double>(cap)});
        }
        case 2:
            return makeCall("glGetString",
                            {static_cast<double>(oneOf({GL_VENDOR, GL_RENDERER, GL_VERSION, GL_EXTENSIONS}))});
        default: {
            const GLenum name = oneOf(kQueryNames);
            return makeCall(
                random_.pick<std::string_view>({"glGetBooleanv", "glGetIntegerv", "glGetFloatv", "glGetDoublev"}),
                {static_cast<double>(name)});
        }
        }
    }

    Call readPixelsCall() {
        const double w = stream_.width, h = stream_.height;
        std::vector<double> args;
        if (random_.chance(badness_ > 0 ? 0.5 : 0.1)) {  // bad rectangles
            args = {random_.pick({kIntMin, -kIntMax, -1e6, -3.0, 0.0, 5.0, 1e6, kIntMax - 10}),
                    random_.pick({kIntMin, -kIntMax, -1e6, -3.0, 0.0, 5.0, 1e6, kIntMax - 10}),
                    random_.pick({-1.0, 0.0, 1.0, 7.0, 100000.0, kIntMax, kIntMax / 2}),
                    random_.pick({-1.0, 0.0, 1.0, 3.0, 100000.0, kIntMax, kIntMax / 2})};
        } else {
            args = {std::round(random_.uniform(-0.3, 1) * w), std::round(random_.uniform(-0.3, 1) * h),
                    std::round(random_.uniform(0, 1.3) * w), std::round(random_.uniform(0, 1.3) * h)};
        }
        std::pair<GLenum, GLenum> formatType =
            random_.pick<std::pair<GLenum, GLenum>>({{GL_RGBA, GL_UNSIGNED_BYTE},
                                                     {GL_RGB, GL_UNSIGNED_BYTE},
                                                     {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT},
                                                     {GL_DEPTH_COMPONENT, GL_FLOAT}});
        if (random_.chance(invalidEnumRate_)) {
            formatType = random_.pick<std::pair<GLenum, GLenum>>({{GL_COLOR_INDEX, GL_UNSIGNED_BYTE},
                                                                  {GL_STENCIL_INDEX, GL_UNSIGNED_BYTE},
                                                                  {0x1234, GL_UNSIGNED_BYTE},
                                                                  {GL_RGBA, 0x1234},
                                                                  {GL_RGBA, GL_BITMAP}});
        }
        args.push_back(formatType.first);
        args.push_back(formatType.second);
        // Keep the destination allocatable: one row if all rows would not fit.
        const auto bytes = [&] {
            const auto at = [&](int i) { return static_cast<std::int64_t>(args[i]); };
            return readPixelsBytes(at(0), at(1), at(2), at(3), formatType.first == GL_RGB ? 3 : 4, stream_.width,
                                   stream_.height);
        };
        if (bytes() > kReadPixelsBytesMax) args[3] = 1;
        if (bytes() > kReadPixelsBytesMax) args[2] = w;
        return makeCall("glReadPixels", args);
    }

    void clear() {
        if (random_.chance(0.5)) emit(stateCall());  // often a clear colour
        if (random_.chance(0.5))
            emit("glClearDepth", {as("d", random_.chance(0.5) ? random_.unit() : random_.pick({0.0, 0.5, 1.0}))});
        GLbitfield mask = random_.pick<GLbitfield>(
            {GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT,
             GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT});
        if (random_.chance(invalidEnumRate_)) mask |= random_.pick<GLbitfield>({0x1, 0x80000000u});
        emit("glClear", {static_cast<double>(mask)});
    }

    Call rectCall() {
        const std::string t = random_.pick<std::string>({"s", "i", "f", "d"});
        const Point a = place(random_.uniform(-1, 1), random_.uniform(-1, 1), 0);
        const Point b = place(random_.uniform(-1, 1), random_.uniform(-1, 1), 0);
        return makeCall("glRect" + t + (random_.chance(0.5) ? "v" : ""),
                        {as(t, a.x), as(t, a.y), as(t, b.x), as(t, b.y)});
    }

    // glPushAttrib/glPopAttrib and their client forms between episodes, now and then past the
    // stacks' depth. They draw from a random source of their own, so that the rest of each seed's
    // stream is what it was before they existed.
    void attribStackCall() {
        RandomSource& r = attribRandom_;
        if (!r.chance(0.35)) return;
        constexpr GLbitfield kGroups[] = {GL_CURRENT_BIT,  GL_POINT_BIT,        GL_LINE_BIT,     GL_POLYGON_BIT,
                                          GL_LIGHTING_BIT, GL_DEPTH_BUFFER_BIT, GL_VIEWPORT_BIT, GL_TRANSFORM_BIT,
                                          GL_ENABLE_BIT,   GL_COLOR_BUFFER_BIT, GL_HINT_BIT,     GL_LIST_BIT};
        const auto times = r.chance(0.05) ? r.integer(1, 20) : 1;
        for (std::int64_t i = 0; i < times; ++i) {
            switch (r.integer(0, 5)) {
            case 0:
            case 1: {
                GLbitfield mask = r.chance(0.2) ? GL_ALL_ATTRIB_BITS : 0;
                for (auto n = r.integer(1, 3); n > 0; --n) mask |= kGroups[r.integer(0, std::size(kGroups) - 1)];
                emit("glPushAttrib", {static_cast<double>(mask)});
                break;
            }
            case 2:
            case 3: emit("glPopAttrib"); break;
            case 4:
                emit("glPushClientAttrib",
                     {static_cast<double>(r.pick<GLbitfield>(
                         {GL_CLIENT_PIXEL_STORE_BIT, GL_CLIENT_VERTEX_ARRAY_BIT, GL_CLIENT_ALL_ATTRIB_BITS}))});
                break;
            default: emit("glPopClientAttrib");
            }
        }
    }

    // Lighting, fog, polygon offset, clip planes and display lists, between episodes. They draw
    // from a random source of their own, swapped in while they are made, so that the rest of each
    // seed's stream is what it was before they existed.
    void featureCalls() {
        std::swap(random_, featureRandom_);
        if (random_.chance(0.3)) {
            switch (random_.integer(0, 6)) {
            case 0:
            case 1: lightingCalls(); break;
            case 2: fogCalls(); break;
            case 3: offsetCalls(); break;
            case 4: clipPlaneCalls(); break;
            case 5: listCalls(); break;
            default: emit(featureQuery()); break;
            }
        }
        std::swap(random_, featureRandom_);
    }

    void enableOrDisable(GLenum cap, double enableRate = 0.7) {
        emit(random_.chance(enableRate) ? "glEnable" : "glDisable", {static_cast<double>(cap)});
    }
    // GL_LIGHT0 + i or GL_CLIP_PLANE0 + i for i below `count`, now and then one past the last.
    GLenum numbered(GLenum first, int count) {
        if (random_.chance(invalidEnumRate_)) return first + static_cast<GLenum>(count);
        return first + static_cast<GLenum>(random_.integer(0, count - 1));
    }
    double inRange(double low, double high, std::initializer_list<double> bad) {
        if (random_.chance(badness_)) return random_.pick(bad);
        return as("f", random_.uniform(low, high));
    }
    std::vector<double> colorValues() {
        return {anyOf("f", -0.5, 1.5), anyOf("f", -0.5, 1.5), anyOf("f", -0.5, 1.5), anyOf("f", -0.5, 1.5)};
    }

    void lightingCalls() {
        if (random_.chance(0.4)) enableOrDisable(GL_LIGHTING, 0.8);
        for (auto n = random_.integer(1, 5); n > 0; --n) {
            const GLenum light = numbered(GL_LIGHT0, 8);
            const GLenum face = oneOf({GL_FRONT, GL_BACK, GL_FRONT_AND_BACK});
            switch (random_.integer(0, 9)) {
            case 0: enableOrDisable(light); break;
            case 1: {
                const GLenum pname = oneOf({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION});
                std::vector<double> args{static_cast<double>(light), static_cast<double>(pname)};
                const std::vector<double> v = colorValues();
                args.insert(args.end(), v.begin(), v.end());
                if (pname == GL_POSITION && random_.chance(0.5)) args[5] = random_.pick({0.0, 1.0});
                emit(random_.chance(0.8) ? "glLightfv" : "glLightiv", args);
                break;
            }
            case 2: {
                const GLenum pname = oneOf({GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                            GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION});
                double value = pname == GL_SPOT_EXPONENT ? inRange(0, 128, {-1.0, 129.0, kNaN})
                               : pname == GL_SPOT_CUTOFF
                                   ? (random_.chance(0.3) ? 180.0 : inRange(0, 90, {-1.0, 91.0, 179.0}))
                                   : inRange(0, 2, {-0.5, 1e30});
                emit(random_.chance(0.8) ? "glLightf" : "glLighti",
                     {static_cast<double>(light), static_cast<double>(pname), value});
                break;
            }
            case 3:
            case 4: {
                const GLenum pname =
                    oneOf({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE, GL_SHININESS});
                std::vector<double> args{static_cast<double>(face), static_cast<double>(pname)};
                const std::vector<double> v = pname == GL_SHININESS
                                                  ? std::vector<double>{inRange(0, 128, {-1.0, 129.0}), 0, 0, 0}
                                                  : colorValues();
                args.insert(args.end(), v.begin(), v.end());
                emit(random_.chance(0.8) ? "glMaterialfv" : "glMaterialiv", args);
                break;
            }
            case 5:
                emit(random_.chance(0.7) ? "glMaterialf" : "glMateriali",
                     {static_cast<double>(face), static_cast<double>(oneOf({GL_SHININESS})),
                      inRange(0, 128, {-1.0, 200.0})});
                break;
            case 6: {
                std::vector<double> args{static_cast<double>(oneOf({GL_LIGHT_MODEL_AMBIENT}))};
                const std::vector<double> v = colorValues();
                args.insert(args.end(), v.begin(), v.end());
                emit(random_.chance(0.8) ? "glLightModelfv" : "glLightModeliv", args);
                break;
            }
            case 7:
                emit(random_.chance(0.5) ? "glLightModeli" : "glLightModelf",
                     {static_cast<double>(oneOf({GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE})),
                      static_cast<double>(random_.integer(0, 1))});
                break;
            case 8:
                emit("glColorMaterial",
                     {static_cast<double>(face), static_cast<double>(oneOf({GL_EMISSION, GL_AMBIENT, GL_DIFFUSE,
                                                                            GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE}))});
                enableOrDisable(GL_COLOR_MATERIAL);
                break;
            default: enableOrDisable(random_.pick<GLenum>({GL_NORMALIZE, kRescaleNormal}));
            }
        }
    }

    void fogCalls() {
        if (random_.chance(0.5)) enableOrDisable(GL_FOG, 0.8);
        for (auto n = random_.integer(1, 4); n > 0; --n) {
            switch (random_.integer(0, 3)) {
            case 0:
                emit(random_.chance(0.7) ? "glFogi" : "glFogf",
                     {GL_FOG_MODE, static_cast<double>(oneOf({GL_LINEAR, GL_EXP, GL_EXP2}))});
                break;
            case 1: emit("glFogf", {GL_FOG_DENSITY, inRange(0, 3, {-1.0, kInf})}); break;
            case 2:
                emit(random_.chance(0.8) ? "glFogf" : "glFogi",
                     {static_cast<double>(oneOf({GL_FOG_START, GL_FOG_END})), inRange(-1, 5, {kNaN, 1e30})});
                break;
            default: {
                std::vector<double> args{static_cast<double>(oneOf({GL_FOG_COLOR}))};
                const std::vector<double> v = colorValues();
                args.insert(args.end(), v.begin(), v.end());
                emit(random_.chance(0.8) ? "glFogfv" : "glFogiv", args);
            }
            }
        }
    }

    void offsetCalls() {
        if (random_.chance(0.7))
            emit("glPolygonOffset", {inRange(-2, 2, {kNaN, 1e30, -kInf}), inRange(-4, 4, {kNaN, 1e30})});
        enableOrDisable(oneOf({GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT}));
    }

    void clipPlaneCalls() {
        const GLenum plane = numbered(GL_CLIP_PLANE0, 6);
        if (random_.chance(0.8)) {
            emit("glClipPlane",
                 {static_cast<double>(plane), as("d", random_.uniform(-1, 1)), as("d", random_.uniform(-1, 1)),
                  as("d", random_.uniform(-1, 1)), as("d", random_.uniform(-0.5, 0.5))});
        }
        enableOrDisable(plane, 0.6);
    }

    // A display list compiled around an episode (executed too, or not), called now or later.
    void listCalls() {
        const double list = static_cast<double>(random_.integer(1, 4));
        if (random_.chance(0.5)) {
            emit("glNewList",
                 {random_.chance(0.97) ? list : 0.0, static_cast<double>(oneOf({GL_COMPILE, GL_COMPILE_AND_EXECUTE}))});
            for (auto n = random_.integer(1, 3); n > 0; --n) episode();
            emit("glEndList");
        }
        if (random_.chance(0.7)) emit("glCallList", {list});
        if (random_.chance(0.1)) emit("glDeleteLists", {list, static_cast<double>(random_.integer(1, 2))});
        if (random_.chance(0.05))
            emit("glListBase", {static_cast<double>(random_.integer(0, 3))});  // glCallList ignores it
    }

    Call featureQuery() {
        static constexpr GLenum kNames[] = {GL_LIGHTING,
                                            GL_LIGHT0,
                                            GL_LIGHT5,
                                            GL_COLOR_MATERIAL,
                                            GL_COLOR_MATERIAL_FACE,
                                            GL_COLOR_MATERIAL_PARAMETER,
                                            GL_LIGHT_MODEL_AMBIENT,
                                            GL_LIGHT_MODEL_LOCAL_VIEWER,
                                            GL_LIGHT_MODEL_TWO_SIDE,
                                            GL_NORMALIZE,
                                            GL_MAX_LIGHTS,
                                            GL_FOG,
                                            GL_FOG_MODE,
                                            GL_FOG_DENSITY,
                                            GL_FOG_START,
                                            GL_FOG_END,
                                            GL_FOG_COLOR,
                                            GL_POLYGON_OFFSET_FACTOR,
                                            GL_POLYGON_OFFSET_UNITS,
                                            GL_POLYGON_OFFSET_FILL,
                                            GL_POLYGON_OFFSET_LINE,
                                            GL_CLIP_PLANE0,
                                            GL_CLIP_PLANE3,
                                            GL_MAX_CLIP_PLANES,
                                            GL_LIST_INDEX,
                                            GL_LIST_MODE,
                                            GL_LIST_BASE,
                                            GL_MAX_LIST_NESTING};
        const GLenum face = oneOf({GL_FRONT, GL_BACK});
        switch (random_.integer(0, 5)) {
        case 0:
            return makeCall(
                random_.chance(0.5) ? "glGetLightfv" : "glGetLightiv",
                {static_cast<double>(numbered(GL_LIGHT0, 8)),
                 static_cast<double>(oneOf({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                            GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                            GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION}))});
        case 1:
            return makeCall(
                random_.chance(0.5) ? "glGetMaterialfv" : "glGetMaterialiv",
                {static_cast<double>(face),
                 static_cast<double>(oneOf({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS}))});
        case 2: return makeCall("glGetClipPlane", {static_cast<double>(numbered(GL_CLIP_PLANE0, 6))});
        case 3: return makeCall("glIsList", {static_cast<double>(random_.integer(0, 5))});
        default:
            return makeCall(random_.pick<std::string_view>(
                                {"glGetBooleanv", "glGetIntegerv", "glGetFloatv", "glGetDoublev", "glIsEnabled"}),
                            {static_cast<double>(oneOf(kNames))});
        }
    }

    void stackAbuse() {
        emit("glMatrixMode", {static_cast<double>(random_.pick<GLenum>({GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE}))});
        for (auto n = random_.integer(1, 40); n > 0; --n) emit("glPushMatrix");
        emit("glGetError");
        for (auto n = random_.integer(0, 45); n > 0; --n) emit("glPopMatrix");
        emit("glGetError");
        emit("glMatrixMode", {GL_MODELVIEW});
    }

    RandomSource random_;
    RandomSource attribRandom_;
    RandomSource featureRandom_;
    std::optional<PixelFeatureCalls> pixelFeatures_;  // made once the stream's size and badness are drawn
    AvoidedCounts& avoided_;
    Stream stream_;
    StreamContext context_;
    double badness_ = 0;          // the rate at which a value is replaced by a bad one
    double invalidEnumRate_ = 0;  // the rate at which an enum is replaced by an invalid one
    bool pixelSpace_ = false;     // the projection maps object coordinates to window pixels
    bool bigDrawLeft_ = false;    // this stream may still draw one block of 10k-100k vertices
};

}  // namespace

Stream generateStream(std::uint64_t seed, const GeneratorOptions& options, AvoidedCounts& avoided) {
    return Generator(seed, options, avoided).generate();
}

}  // namespace fuzz
