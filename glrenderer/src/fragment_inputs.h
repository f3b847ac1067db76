#pragma once
#include <cstdint>
#include <span>

#include "fragment_key.h"
#include "glrenderer/fog.h"
#include "glrenderer/framebuffer.h"
#include "glrenderer/stats.h"
#include "triangle_setup.h"

namespace glrenderer {

struct RasterTriangle;
struct PixelRect;
struct FragmentInputs;

// The per-fragment operations' constants of a draw (issue 16), read by keys that have them.
struct FragmentOpsConstants {
    std::uint8_t alphaRef = 0;
    std::uint8_t stencilRef = 0, stencilValueMask = 0xFF, stencilWriteMask = 0xFF;
    std::uint32_t colorMask = 0xFFFFFFFF;

    static FragmentOpsConstants of(const FragmentOps& ops) {
        return {ops.alphaRef, ops.stencil.ref, ops.stencil.valueMask, ops.stencil.writeMask, ops.colorMask};
    }
    bool operator==(const FragmentOpsConstants&) const = default;
};

struct FragmentCounts {
    std::uint64_t fragments = 0, passed = 0;
};

// Every fragment that passes writes its pixel (counted so even under a colour mask).
inline void addFragmentCounts(Stats& stats, const FragmentCounts& counts) {
    stats.fragments += counts.fragments;
    stats.fragmentsPassed += counts.passed;
    stats.pixelsWritten += counts.passed;
}

// The fragment stage for one key at one vector width, over the pixel sets that coverage makes.
struct FragmentRoutine {
    // The pixels [begin, end] of internal row `row` (y down), all covered by the primitive.
    using Span = void (*)(const FragmentInputs& inputs, int row, int begin, int end, Framebuffer& framebuffer,
                          FragmentCounts& counts);
    // A narrow triangle's part in `area` (its bounds within a tile), in 2D blocks of lanes with
    // their own coverage test, no span search; returns false, drawing nothing, if the area is
    // too wide for the blocks.
    using Narrow = bool (*)(const RasterTriangle& triangle, const PixelRect& area, Framebuffer& framebuffer,
                            FragmentCounts& counts);
    // A triangle's part in `area`, row by row: each row's covered span from the edge functions
    // (the whole width of the area when `coveredWhole`), the lanes set up once for all rows.
    using Rows = void (*)(const RasterTriangle& triangle, const PixelRect& area, bool coveredWhole,
                          Framebuffer& framebuffer, FragmentCounts& counts);

    // Consecutive triangles of one tile (`area` its rectangle), in order, from the first up to
    // one of another routine: the fragments of several tiny ones packed into one block of lanes,
    // the others as by rasterizeTriangleSpans. Returns how many it drew (at least one).
    using Packed = std::size_t (*)(std::span<const RasterTriangle* const> triangles, const PixelRect& area,
                                   Framebuffer& framebuffer, FragmentCounts& counts);

    Span span = nullptr;
    Rows rows = nullptr;
    Narrow narrow = nullptr;  // optional
    Packed packed = nullptr;  // optional: for fast keys without texturing, at widths that pack
    // The passes of deferred shading (DeferredPass), for a fast key that defersColor().
    const FragmentRoutine* visibility = nullptr;
    const FragmentRoutine* shade = nullptr;
    // A fast path's own key; null for the routine of any key, which reads the primitive's
    // (FragmentInputs::key).
    const FragmentKey* key = nullptr;
};

// A key and the routine that serves it on this CPU.
struct FragmentPath {
    FragmentKey key;
    const FragmentRoutine* routine = nullptr;
};

// What the fragment stage needs of one primitive: planes of its attributes over the window,
// evaluated at pixel (x, y) in internal rows, and the path that draws them. Only the planes the
// key reads are set.
struct FragmentInputs {
    // The routine first, then the planes most keys read, then the rest: a triangle's setup
    // writes and its tiles read only the cache lines its key uses (RasterTriangle).
    const FragmentRoutine* routine = nullptr;
    FragmentOpsConstants ops;  // (issue 16)
    AttributePlanes<4> color;  // colour, or colour / w under perspective shading
    // 1 / w under perspective shading, and window z with the depth test (invW(), depth()): side
    // by side, as a triangle's setup computes them.
    AttributePlanes<2> invWAndDepth;
    std::uint32_t flatColor = 0;  // the fragment colour word under flat shading
    float depthOffset = 0.0f;     // polygon offset, with a key that has it
    // Fog (issue 16), with a key that has it: the fog coordinate's plane, divided by w as a
    // perspective colour's is (invW and the colour planes are set too, constant under flat
    // shading), and the draw's constants.
    AttributePlane fogCoord;
    // The key, with the routine of any key only (a fast path's routine has its own: key()).
    FragmentKey anyKey;
    const PolygonStipplePattern* polygonStipple = nullptr;  // with a key that has it (interned)
    AttributePlane secondaryColor[3];  // the same of the secondary colour, with a key that has the colour sum
    FogState fog;
    // Texturing (issue 16), with a key that has it: planes of s, t and q divided by w (invW is
    // set too) and the draw's texture.
    AttributePlane texCoord[3];
    const Texture* texture = nullptr;
    glm::vec4 textureEnvColor{0.0f}, textureBorderColor{0.0f};

    // The texture planes of s, t and q through `planes` (a PlaneBuilder or a line's), each
    // coordinate divided by w as a perspective colour is, with the plane of 1 / w.
    // The draw's texture and its colours, for planes set up elsewhere.
    void setTextureImage(const Texture* image, const glm::vec4& envColor, const glm::vec4& borderColor) {
        texture = image;
        textureEnvColor = envColor;
        textureBorderColor = borderColor;
    }
    template <class Planes, class... Vertices>
    void setTexture(const Texture* image, const glm::vec4& envColor, const glm::vec4& borderColor, const Planes& planes,
                    const Vertices&... v);

    // The colour of a flat primitive: its word, and with fog, texturing or the colour sum its
    // constant planes (and the secondary colour's).
    void setFlatColor(const glm::vec4& color, const glm::vec3& secondary = glm::vec3(0.0f));

    // The routine, and the key where the routine does not carry it: the record of a fast path's
    // triangle is one cache line shorter without it.
    void setPath(const FragmentPath& path) {
        routine = path.routine;
        if (!routine->key) anyKey = path.key;
    }
    // The key of the routine that draws the primitive (a fast path serves a flat key that reads
    // its colour planes with its linear key's routine, bit for bit: routineKey).
    const FragmentKey& key() const { return routine->key ? *routine->key : anyKey; }
    AttributePlane invW() const { return invWAndDepth[0]; }
    AttributePlane depth() const { return invWAndDepth[1]; }
    void setInvW(const AttributePlane& plane) { invWAndDepth.set(0, plane); }
    void setDepth(const AttributePlane& plane) { invWAndDepth.set(1, plane); }
    // Draws the pixels [begin, end] of `row` with the primitive's routine.
    void shadeSpan(int row, int begin, int end, Framebuffer& framebuffer, FragmentCounts& counts) const {
        routine->span(*this, row, begin, end, framebuffer, counts);
    }
};

// Whether two primitives of `key` share the draw's constants the key reads: all it reads but
// their planes, flat colour and depth offset (FragmentLanes::take), for a key whose texels
// colour the fragments if any (TexelUse::Color).
[[gnu::always_inline]] inline bool sameDrawConstants(const FragmentKey& key, const FragmentInputs& a,
                                                     const FragmentInputs& b) {
    const bool readsOps = key.alphaFunc != CompareFunc::Always || key.stencilTest || key.colorMask;
    return (!readsOps || a.ops == b.ops) && (!key.polygonStipple || a.polygonStipple == b.polygonStipple) &&
           (key.fog == FogMode::Off || a.fog == b.fog) &&
           (!key.texturesColor() || (a.texture == b.texture && a.textureEnvColor == b.textureEnvColor &&
                                     a.textureBorderColor == b.textureBorderColor));
}

}  // namespace glrenderer

namespace glrenderer {

template <class Planes, class... Vertices>
void FragmentInputs::setTexture(const Texture* image, const glm::vec4& envColor, const glm::vec4& borderColor,
                                const Planes& planes, const Vertices&... v) {
    setTextureImage(image, envColor, borderColor);
    setInvW(planes.plane(v.invW...));
    texCoord[0] = planes.plane((v.texCoord.s * v.invW)...);
    texCoord[1] = planes.plane((v.texCoord.t * v.invW)...);
    texCoord[2] = planes.plane((v.texCoord.q * v.invW)...);
}

}  // namespace glrenderer
