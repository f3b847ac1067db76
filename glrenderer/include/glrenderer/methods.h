#pragma once
#include <optional>
#include <string_view>

namespace glrenderer {

// How triangles are turned into pixels. Exact is the default and the only one that follows the
// reference's rules; the others are the seed documents' methods, kept to chart speed against
// accuracy and to show where each one breaks.
enum class RasterMethod {
    Exact,             // fixed-point 1/256 edge functions, covered spans, SIMD shading
    ExactPerPixel,     // the same rules tested pixel by pixel: the scalar reference kernel
    Scanline,          // float edge slopes per scanline, ceil(x - 0.5) (seed 001)
    BoundingBoxFloat,  // float edge functions over the bounding box, edges inclusive (seed 004)
};

enum class Interpolation {
    PerspectiveCorrect,  // attributes / w interpolated, divided per pixel (GL, the reference)
    ScreenLinear,        // attributes interpolated linearly in window space (the course)
};

// How a triangle's facing is decided; glCullFace and glFrontFace then apply as GL defines.
enum class CullMethod {
    WindowArea,       // sign of the snapped window-space area (GL, the reference)
    ViewSpaceNormal,  // (v1 - v0) x (v2 - v0) against the vector to v0, in eye space (seed 000)
    LookVector,       // the first vertex's normal against the look vector (seed 003: fails in perspective)
};

enum class HiddenSurface {
    AsEnabled,     // the depth buffer when GL_DEPTH_TEST is on (GL)
    PaintersSort,  // no depth buffer: triangles drawn far to near by mean depth (seed 000), per tile
};

struct Methods {
    RasterMethod raster = RasterMethod::Exact;
    Interpolation interpolation = Interpolation::PerspectiveCorrect;
    CullMethod culling = CullMethod::WindowArea;
    HiddenSurface hiddenSurface = HiddenSurface::AsEnabled;
    // Whether vertices must carry eye-space position and normal (only the seeds' culling needs it).
    bool needsEyeSpace() const { return culling != CullMethod::WindowArea; }
    bool operator==(const Methods&) const = default;
};

std::string_view toString(RasterMethod method);
std::optional<RasterMethod> parseRasterMethod(std::string_view name);

}  // namespace glrenderer
