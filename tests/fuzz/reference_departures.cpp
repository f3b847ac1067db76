#include "reference_departures.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string_view>

namespace fuzz {
namespace {

// The digit after the prefix of "glVertex3f", "glColor4ub": the number of components.
int components(std::string_view name, std::string_view prefix) { return name[prefix.size()] - '0'; }

bool isIntegerColor(std::string_view name) { return !name.ends_with("f") && !name.ends_with("d") && !name.ends_with("fv") && !name.ends_with("dv"); }

bool isIntegerMatrixQuery(const Call& call, const StreamContext&) {
    if (functionName(call) != "glGetIntegerv") return false;
    const auto pname = static_cast<GLenum>(call.args[0]);
    return pname == GL_MODELVIEW_MATRIX || pname == GL_PROJECTION_MATRIX || pname == GL_TEXTURE_MATRIX;
}

bool isColor3AfterIntegerColor(const Call& call, const StreamContext& context) {
    return functionName(call).starts_with("glColor3") && context.lastColorWasInteger;
}

bool growsLineLoopFormat(const Call& call, const StreamContext& c) {
    if (!c.insideBegin || c.mode != GL_LINE_LOOP || c.verticesInBlock == 0) return false;
    const std::string_view name = functionName(call);
    if (name.starts_with("glVertex")) return components(name, "glVertex") > c.firstVertexSize;
    if (name.starts_with("glColor")) return components(name, "glColor") > c.colorSizeAtFirstVertex;
    if (name.starts_with("glNormal")) return !c.normalAtFirstVertex;
    if (name.starts_with("glTexCoord")) return !c.texCoordAtFirstVertex;
    if (name.starts_with("glEdgeFlag")) return !c.edgeFlagAtFirstVertex;
    return false;
}

bool readsNearIntMax(const Call& call, const StreamContext&) {
    if (functionName(call) != "glReadPixels") return false;
    constexpr std::int64_t kLimit = std::numeric_limits<GLint>::max() - (1 << 20);
    const auto x = static_cast<std::int64_t>(call.args[0]), y = static_cast<std::int64_t>(call.args[1]);
    const auto w = static_cast<std::int64_t>(call.args[2]), h = static_cast<std::int64_t>(call.args[3]);
    return x + w > kLimit || y + h > kLimit || x > kLimit || y > kLimit;
}

constexpr Departure kDepartures[] = {
    {"integer-query-of-matrix",
     "glGetIntegerv of a matrix: OSMesa maps entries like colours ([-1,1] to the integer range), the spec rounds them",
     isIntegerMatrixQuery},
    {"color3-after-integer-color",
     "glColor3* after a glColor of an integer type: OSMesa keeps the old alpha, the spec sets it to 1",
     isColor3AfterIntegerColor},
    {"line-loop-format-growth",
     "an attribute new to a GL_LINE_LOOP after its first vertex: OSMesa flushes the loop and loses its closing segment",
     growsLineLoopFormat},
    {"read-pixels-near-int-max",
     "glReadPixels whose rectangle reaches within 2^20 of INT_MAX: OSMesa's clipping overflows and it crashes",
     readsNearIntMax},
};

}  // namespace

void StreamContext::update(const Call& call) {
    const std::string_view name = functionName(call);
    if (name == "glBegin") {
        if (insideBegin || call.args[0] > GL_POLYGON) return;  // an error: nothing begins
        *this = StreamContext{.insideBegin = true, .mode = static_cast<GLenum>(call.args[0]),
                              .lastColorWasInteger = lastColorWasInteger};
    } else if (name == "glEnd") {
        insideBegin = false;
    } else if (name.starts_with("glColor")) {
        lastColorWasInteger = isIntegerColor(name);
        if (insideBegin) colorSizeInBlock = std::max(colorSizeInBlock, components(name, "glColor"));
    } else if (insideBegin && name.starts_with("glNormal")) {
        normalInBlock = true;
    } else if (insideBegin && name.starts_with("glTexCoord")) {
        texCoordInBlock = true;
    } else if (insideBegin && name.starts_with("glEdgeFlag")) {
        edgeFlagInBlock = true;
    } else if (insideBegin && name.starts_with("glVertex")) {
        if (verticesInBlock++ > 0) return;
        firstVertexSize = components(name, "glVertex");
        colorSizeAtFirstVertex = colorSizeInBlock;
        normalAtFirstVertex = normalInBlock;
        texCoordAtFirstVertex = texCoordInBlock;
        edgeFlagAtFirstVertex = edgeFlagInBlock;
    }
}

std::span<const Departure> referenceDepartures() { return kDepartures; }

const Departure* departureFor(const Call& call, const StreamContext& context) {
    for (const Departure& d : kDepartures) {
        if (d.matches(call, context)) return &d;
    }
    return nullptr;
}

}  // namespace fuzz
