#pragma once
// Our GL entry points, gathered per area and looked up by name in entry_points.cpp. They are
// captureless lambdas with the exact parameter types of glad's PFNGL...PROC typedefs (the GL
// calling convention is the C one on the platforms we build for).
#include <array>
#include <optional>
#include <span>

#include "context_state.h"

namespace mygl {

struct EntryPoint {
    const char* name;
    ProcAddress proc;
};

template <class Function>
ProcAddress entry(Function* function) {
    return reinterpret_cast<ProcAddress>(function);
}
std::span<const EntryPoint> beginEndEntryPoints();
std::span<const EntryPoint> matrixEntryPoints();
std::span<const EntryPoint> stateEntryPoints();
std::span<const EntryPoint> getEntryPoints();
std::span<const EntryPoint> bufferEntryPoints();
std::span<const EntryPoint> listEntryPoints();
std::span<const EntryPoint> arrayEntryPoints();
std::span<const EntryPoint> rasterPosEntryPoints();
std::span<const EntryPoint> pixelRectangleEntryPoints();
std::span<const EntryPoint> pixelModeEntryPoints();
std::span<const EntryPoint> lightingEntryPoints();
std::span<const EntryPoint> selectionEntryPoints();
std::span<const EntryPoint> attribStackEntryPoints();
std::span<const EntryPoint> clipPlaneEntryPoints();
std::span<const EntryPoint> fogEntryPoints();
std::span<const EntryPoint> polygonOffsetEntryPoints();
std::span<const EntryPoint> stippleEntryPoints();
std::span<const EntryPoint> fragmentOpsEntryPoints();
// The colour bits draws write: glColorMask's, none with glDrawBuffer(GL_NONE).
void updateColorWrites(Context::State& state);
std::span<const EntryPoint> evaluatorEntryPoints();
std::span<const EntryPoint> accumulationEntryPoints();
std::span<const EntryPoint> colorIndexEntryPoints();
std::span<const EntryPoint> drawBufferEntryPoints();
std::span<const EntryPoint> feedbackEntryPoints();

// GL_FEEDBACK: the tokens of what the pipeline drew since the last call; a glBitmap's token (after
// those); leaving the mode (the tokens so far, then glRenderMode's answer: the count, or -1 after
// an overflow).
void writeFeedbackPrimitives(Context::State& state);
// The token of a glBitmap, glDrawPixels or glCopyPixels (GL_BITMAP_TOKEN, GL_DRAW_PIXEL_TOKEN,
// GL_COPY_PIXEL_TOKEN) and the raster position, after the primitives before it; nothing when
// the position is invalid.
void writeFeedbackRasterPosition(Context::State& state, GLenum token);
GLint endFeedback(Context::State& state);

// glClear's GL_ACCUM_BUFFER_BIT: the accumulation buffer filled with glClearAccum's value.
void clearAccumBuffer(Context::State& state);
std::span<const EntryPoint> textureEntryPoints();
std::span<const EntryPoint> textureParameterEntryPoints();
std::span<const EntryPoint> textureGenEntryPoints();

// The current context if a call that is not allowed between glBegin and glEnd may proceed:
// nullptr without a context, and nullptr plus GL_INVALID_OPERATION inside glBegin/glEnd.
Context::State* stateOutsideBeginEnd();

// Called before a state change: the reference's vertex buffer flushes there, ending the batch.
// glEnable/glDisable of GL_LIGHTING, GL_LIGHTi, GL_NORMALIZE, GL_RESCALE_NORMAL and
// GL_COLOR_MATERIAL (false for other capabilities), and their glIsEnabled (nullopt for others).
bool setLightingCapability(Context::State& state, GLenum cap, bool enabled);
// The draw state's lit colours (two-sided, separate specular) from the lighting state.
void updateLitColors(Context::State& state);
// The same for GL_CLIP_PLANEi; and the clip-space planes again from the current projection.
bool setClipPlaneCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> clipPlaneCapability(const Context::State& state, GLenum cap);
void updateClipPlanes(Context::State& state);
// The same for GL_MAPn_* and GL_AUTO_NORMAL.
bool setEvaluatorCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> evaluatorCapability(const Context::State& state, GLenum cap);
std::optional<bool> lightingCapability(const Context::State& state, GLenum cap);

// Lighting is prepared again after any state change.
inline void endBatch(Context::State& state) {
    state.pipeline.endBatch();
    state.lightingStale = true;
}

}  // namespace mygl
