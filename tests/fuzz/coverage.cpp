#include "coverage.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "gl_enum_names.h"
#include "reference_departures.h"

namespace fuzz {
namespace {

constexpr double kFloatMin = 1.17549435e-38;  // the smallest normal float

bool isExtreme(double v, double limit) { return !(std::abs(v) < limit); }

// The bad-input classes one call belongs to.
void classify(const Call& call, const StreamContext& context, std::map<std::string, std::size_t>& counts) {
    const std::string_view name = functionName(call);
    const auto& a = call.args;
    for (double v : a) {
        if (std::isnan(v))
            ++counts["NaN"];
        else if (std::isinf(v))
            ++counts["Inf"];
        else if (std::abs(v) >= 1e30)
            ++counts["1e30+"];
        else if (v != 0 && std::abs(v) < kFloatMin)
            ++counts["denormal"];
    }
    if (name.starts_with("glVertex4")) {
        if (a[3] <= 0)
            ++counts["w<=0"];
        else if (a[3] < 1e-3)
            ++counts["w~0"];
    }
    const bool allowedInside = name.starts_with("glVertex") || name.starts_with("glColor") ||
                               name.starts_with("glNormal") || name.starts_with("glTexCoord") ||
                               name.starts_with("glEdgeFlag") || name == "glEnd";
    if (context.insideBegin && !allowedInside) ++counts["illegal in glBegin"];
    if (name == "glViewport" &&
        (a[2] < 0 || a[3] < 0 || isExtreme(a[0], 1e5) || isExtreme(a[1], 1e5) || a[2] > 16384 || a[3] > 16384))
        ++counts["extreme viewport"];
    if (name == "glDepthRange" && (isExtreme(a[0] - 0.5, 0.5) || isExtreme(a[1] - 0.5, 0.5) || a[0] > a[1]))
        ++counts["odd depth range"];
    if (name == "glReadPixels" &&
        (a[2] < 0 || a[3] < 0 || isExtreme(a[0], 1e6) || isExtreme(a[1], 1e6) || a[2] > 1e5 || a[3] > 1e5))
        ++counts["bad read rectangle"];
    if (name == "glBegin" && a[0] > GL_POLYGON) ++counts["bad glBegin mode"];
    if (name == "glEnd" && context.insideBegin && context.verticesInBlock >= 10000) ++counts["10k+ vertex block"];
}

// The texture-image paths one call takes: a colour-index image, an image after a colour
// transfer (scale, bias, GL_MAP_COLOR) was set.
void classifyTextureImage(const Call& call, const StreamContext& context, std::map<std::string, std::size_t>& counts) {
    std::size_t widthAt = 0, formatAt = 0;
    if (!textureImageArguments(functionName(call), widthAt, formatAt)) return;
    if (static_cast<GLenum>(call.args[formatAt]) == GL_COLOR_INDEX) ++counts["colour index"];
    if (context.colorTransferEverSet) ++counts["after a colour transfer"];
}

}  // namespace

void Coverage::add(const Stream& stream, const Outcome& reference) {
    StreamContext context;
    for (const Call& call : stream.calls) {
        ++calls_[std::string(functionName(call))];
        classify(call, context, badInput_);
        classifyTextureImage(call, context, textureImages_);
        context.update(call);
    }
    for (const Answer& a : reference.answers) {
        if (a.kind != AnswerKind::Error) continue;
        GLenum e;
        std::memcpy(&e, a.bytes.data(), sizeof e);
        if (e != GL_NO_ERROR) ++errors_[e];
    }
}

std::string Coverage::summary() const {
    std::ostringstream text;
    text << "  entry points called: " << calls_.size() << " of " << functionCount();
    bool allCalled = true;
    for (std::uint16_t id = 0; id < functionCount(); ++id) {
        const std::string_view name = functionName(Call{id, {}});
        if (calls_.contains(std::string(name))) continue;
        text << (allCalled ? " (never:" : "") << " " << name;
        allCalled = false;
    }
    text << (allCalled ? "" : ")") << "\n  bad input (calls):";
    for (const auto& [what, n] : badInput_) text << " " << what << " " << n << ",";
    text << "\n  texture images (glTexImage, glTexSubImage):";
    for (const auto& [what, n] : textureImages_) text << " " << what << " " << n << ",";
    text << "\n  errors the reference raised:";
    for (const auto& [e, n] : errors_) text << " " << enumName(e) << " " << n << ",";
    text << "\n";
    return text.str();
}

}  // namespace fuzz
