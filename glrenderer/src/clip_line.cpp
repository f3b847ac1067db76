#include "clip_line.h"

#include <algorithm>
#include <cmath>

#include "clip.h"

namespace glrenderer {
namespace {

// `from` moved by fraction t towards `to`.
ClipVertex moveTowards(const ClipVertex& from, const ClipVertex& to, float t) {
    ClipVertex v = from;
    v.position = from.position + t * (to.position - from.position);
    v.color = from.color + t * (to.color - from.color);
    v.fogCoord = from.fogCoord + t * (to.fogCoord - from.fogCoord);
    v.texCoord = from.texCoord + t * (to.texCoord - from.texCoord);
    return v;
}

}  // namespace

bool clipLine(ClipVertex& a, ClipVertex& b, Outcode outcodeA, Outcode outcodeB, const UserClipPlanes& user) {
    const Outcode planes = outcodeA | outcodeB;
    if (planes == 0) return true;
    if (outcodeA & outcodeB) return false;
    float tA = 0.0f, tB = 0.0f;
    for (int plane = 0; plane < kClipPlaneCount; ++plane) {
        if (!(planes & (1u << plane))) continue;
        const float da = clipPlaneDistance(a.position, plane, user);
        const float db = clipPlaneDistance(b.position, plane, user);
        if (!std::isfinite(da) || !std::isfinite(db)) return false;
        if (db < 0.0f) tB = std::max(tB, db / (db - da));
        if (da < 0.0f) tA = std::max(tA, da / (da - db));
        if (tA + tB >= 1.0f) return false;
    }
    const ClipVertex originalA = a;
    if (outcodeA) a = moveTowards(originalA, b, tA);
    if (outcodeB) b = moveTowards(b, originalA, tB);
    return true;
}

}  // namespace glrenderer
