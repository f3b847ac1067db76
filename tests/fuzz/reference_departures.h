#pragma once
// Where the reference (OSMesa, Mesa 22.3) departs from the GL spec or fails, in one place. MyGL
// follows the spec, so a stream that reaches one of these cases would differ for a reason that
// is not a MyGL bug: the generator drops every call a rule matches and counts it.
#include <glad/gl.h>

#include <span>

#include "gl_call.h"

namespace fuzz {

// What the rules need to know about the stream before a call.
struct StreamContext {
    bool insideBegin = false;
    GLenum mode = GL_POINTS;
    int verticesInBlock = 0;
    // The vertex format of the glBegin/glEnd block as it stood at its first vertex.
    int firstVertexSize = 0;
    int colorSizeAtFirstVertex = 0;  // 0: no colour call in the block before its first vertex
    bool normalAtFirstVertex = false, texCoordAtFirstVertex = false, edgeFlagAtFirstVertex = false;
    int colorSizeInBlock = 0;
    bool normalInBlock = false, texCoordInBlock = false, edgeFlagInBlock = false;
    bool lastColorWasInteger = false;  // the last glColor had an integer type (b, ub, s, us, i, ui)

    void update(const Call& call);  // after `call` was added to the stream
};

struct Departure {
    const char* name;
    const char* reason;  // one line: what the reference does instead of the spec
    bool (*matches)(const Call& call, const StreamContext& context);
};

std::span<const Departure> referenceDepartures();

// The rule `call` would run into after `context`, or nullptr.
const Departure* departureFor(const Call& call, const StreamContext& context);

}  // namespace fuzz
