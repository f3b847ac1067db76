#pragma once
// Where the reference (OSMesa, Mesa 22.3) departs from the GL spec or fails, in one place. MyGL
// follows the spec, so a stream that reaches one of these cases would differ for a reason that
// is not a MyGL bug: the generator drops every call a rule matches and counts it.
#include <glad/gl.h>

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "gl_call.h"

namespace fuzz {

// What the rules need to know about the stream before a call.
struct StreamContext {
    // The attributes a glBegin/glEnd block has set: all of them, and those before its first vertex.
    struct Attributes {
        int vertexSize = 0;  // the first vertex's components
        int colorSize = 0;   // 0: no glColor in the block
        bool normal = false, texCoord = false, edgeFlag = false;
    };
    bool insideBegin = false;
    bool listOpen = false;               // a glNewList opened a list not ended yet
    bool compilingAndExecuting = false;  // inside a glNewList(GL_COMPILE_AND_EXECUTE) that opened
    bool beginFromExecutedList = false;  // the open glBegin came while compiling and executing a list
    GLenum mode = GL_POINTS;
    int verticesInBlock = 0;
    Attributes inBlock, atFirstVertex;

    // Float state with no integer value for glGetIntegerv: outside [-1, 1] for the normalized
    // colour and normal, outside the int range for the rest; NaN for all.
    bool colorBeyondUnit = false, normalBeyondUnit = false;
    bool texCoordBeyondInt = false, lineWidthBeyondInt = false, pointSizeBeyondInt = false;
    bool alphaNotOneSinceFlush = false;  // a glColor4* set an alpha other than 1 since the last glFlush/glFinish
    bool borderedTexture = false;        // a texture image with a border was given
    bool colorSinceFlush = false;        // a glColor came outside glBegin/glEnd since the last glFlush/glFinish
    // GL_POLYGON_OFFSET_FILL, _LINE and _POINT as the stream left them (after a glPopAttrib: FILL
    // off and the others on, as nothing is known).
    bool offsetFill = false, offsetLine = false, offsetPoint = false;
    // The unpack modes a colour-index texture image's rows depend on (nullopt: unknown, after a
    // glPopClientAttrib or a glPixelStoref); whether a glPixelTransfer ever set an index shift
    // other than 0 (even in a list), or one beyond +-24, or a colour scale, bias or GL_MAP_COLOR,
    // or any of these or an index offset (the reference's image transfer).
    std::optional<int> unpackAlignment = 4, unpackRowLength = 0, unpackSkipPixels = 0;
    bool indexShiftEverSet = false, indexShiftEverWide = false, colorTransferEverSet = false;
    bool imageTransferEverSet = false;

    // Each glPushAttrib that pushed: its mask, the flags above as they were then (a pop may
    // bring back their values, so a pop ORs them back in), and whether a call that may change
    // state came after it.
    struct Pushed {
        GLbitfield mask;
        std::array<bool, 6> flags;
        bool changedSince = false;
    };
    std::vector<Pushed> attribStack;

    void update(const Call& call);  // after `call` was added to the stream
};

struct Departure {
    const char* name;
    const char* reason;  // one line: what the reference does instead of the spec
    bool (*matches)(const Call& call, const StreamContext& context);
};

std::span<const Departure> referenceDepartures();

// For glTexImage1D/2D and glTexSubImage1D/2D: the argument positions of the width and the
// format (the type follows it); false for other calls.
bool textureImageArguments(std::string_view name, std::size_t& width, std::size_t& format);

// The rule `call` would run into after `context`, or nullptr.
const Departure* departureFor(const Call& call, const StreamContext& context);

}  // namespace fuzz
