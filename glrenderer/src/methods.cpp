#include "glrenderer/methods.h"

#include <array>
#include <utility>

namespace glrenderer {
namespace {

constexpr std::array<std::pair<RasterMethod, std::string_view>, 4> kNames{{
    {RasterMethod::Exact, "exact"},
    {RasterMethod::ExactPerPixel, "exact-per-pixel"},
    {RasterMethod::Scanline, "scanline"},
    {RasterMethod::BoundingBoxFloat, "bbox-float"},
}};

}  // namespace

std::string_view toString(RasterMethod method) {
    for (const auto& [m, name] : kNames)
        if (m == method) return name;
    return "unknown";
}

std::optional<RasterMethod> parseRasterMethod(std::string_view name) {
    for (const auto& [m, n] : kNames)
        if (n == name) return m;
    return std::nullopt;
}

}  // namespace glrenderer
