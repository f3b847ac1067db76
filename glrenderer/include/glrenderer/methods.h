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

struct Methods {
    RasterMethod raster = RasterMethod::Exact;
    Interpolation interpolation = Interpolation::PerspectiveCorrect;
    bool operator==(const Methods&) const = default;
};

std::string_view toString(RasterMethod method);
std::optional<RasterMethod> parseRasterMethod(std::string_view name);

}  // namespace glrenderer
