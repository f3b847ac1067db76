#pragma once
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

#include "glrenderer/fog.h"
#include "glrenderer/fragment_ops.h"
#include "glrenderer/polygon_offset.h"
#include "glrenderer/stipple.h"
#include "glrenderer/texture.h"

namespace glrenderer {

// The ten glBegin modes, in GL's enum order (GL_POINTS = 0 ... GL_POLYGON = 9).
enum class PrimitiveMode : std::uint8_t {
    Points,
    Lines,
    LineLoop,
    LineStrip,
    Triangles,
    TriangleStrip,
    TriangleFan,
    Quads,
    QuadStrip,
    Polygon
};
inline constexpr int kPrimitiveModeCount = 10;

// How a draw's quads become triangles. ByPath: as the reference's direct path or draw module
// splits them (see decompose.h). V1V3: always (0,1,3), (1,2,3), as the reference's quads arrive
// already converted into indexed triangles from display lists and glDrawElements.
enum class QuadSplit : std::uint8_t { ByPath, V1V3 };

enum class Face : std::uint8_t { Front, Back, FrontAndBack };
enum class ShadeModel : std::uint8_t { Flat, Smooth };
enum class PolygonMode : std::uint8_t { Point, Line, Fill };

struct Viewport {
    int x = 0, y = 0, width = 0, height = 0;
    bool operator==(const Viewport&) const = default;
};

// glClipPlane's planes as the reference clips with them: in clip space (the eye-space plane
// times the inverse of the projection), each used when its bit in `enabled` is set.
struct UserClipPlanes {
    std::array<glm::vec4, 8> planes{};
    std::uint8_t enabled = 0;
    bool operator==(const UserClipPlanes&) const = default;
};

// Everything the pipeline needs to know about GL state for one draw. Plain values, no GL enums.
struct DrawState {
    bool cullEnabled = false;
    Face cullFace = Face::Back;
    bool frontFaceCCW = true;
    bool depthTest = false;
    CompareFunc depthFunc = CompareFunc::Less;
    bool depthWrite = true;
    ShadeModel shadeModel = ShadeModel::Smooth;
    PolygonMode polygonFront = PolygonMode::Fill;
    PolygonMode polygonBack = PolygonMode::Fill;
    Viewport viewport;
    // Kept in float, as the reference keeps them; its depth scale and offset are formed from
    // them in double (depthScale(), depthTranslate()) and only then rounded to float.
    float depthNear = 0.0f, depthFar = 1.0f;
    float lineWidth = 1.0f;
    float pointSize = 1.0f;
    // GL_POINT_SMOOTH and GL_LINE_SMOOTH: drawn as the reference's draw module draws them.
    bool pointSmooth = false, lineSmooth = false;
    bool selection = false;  // GL_SELECT: primitives make hits (Pipeline::takeHits), not pixels
    bool feedback = false;   // GL_FEEDBACK: primitives are handed back (Pipeline::takeFeedback)
    // Two-sided lighting: filled triangles facing back take their vertices' back colours.
    bool twoSidedColors = false;
    // Separate specular colour (GL 1.2): lit vertices carry their specular terms as a secondary
    // colour, interpolated apart and added to the fragment's after the texture environment.
    bool secondaryColors = false;
    UserClipPlanes clipPlanes;
    // Fog (issue 16): its mode (Off when disabled) and constants.
    FogState fog;
    // Polygon offset (issue 16).
    PolygonOffset polygonOffset;
    // Scissor, alpha test, stencil, blending, logic op, colour mask (issue 16).
    FragmentOps fragmentOps;
    // Texturing (issue 16): env Off when disabled.
    TextureState texture;
    // Line and polygon stipple (issue 16).
    LineStipple lineStipple;
    PolygonStipple polygonStipple;
    bool operator==(const DrawState&) const = default;

    float depthScale() const { return static_cast<float>(0.5 * (double(depthFar) - double(depthNear))); }
    float depthTranslate() const { return static_cast<float>(0.5 * (double(depthNear) + double(depthFar))); }
};

}  // namespace glrenderer
