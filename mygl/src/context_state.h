#pragma once
// The GL state machine behind mygl::Context: what the gl* entry points read and change.
#include <glad/gl.h>

#include <glrenderer/framebuffer.h>
#include <glrenderer/lighting.h>
#include <glrenderer/pipeline.h>
#include <array>
#include <map>
#include <vector>

#include <glm/vec3.hpp>

#include "attrib_stack.h"
#include "bitmap_cache.h"
#include "buffer_state.h"
#include "client_arrays.h"
#include "evaluators.h"
#include "feedback.h"
#include "display_lists.h"
#include "selection.h"
#include "stack_matrix.h"
#include "mygl/context.h"
#include "pixel_modes.h"
#include "pixel_store.h"
#include "texture_state.h"
#include "tracked_draw_state.h"

namespace mygl {

class MatrixStack {
public:
    explicit MatrixStack(std::size_t maxDepth) : maxDepth_(maxDepth) {
        stack_.reserve(maxDepth);
        stack_.emplace_back();
    }
    StackMatrix& top() { return stack_.back(); }
    const StackMatrix& top() const { return stack_.back(); }
    std::size_t depth() const { return stack_.size(); }
    std::size_t maxDepth() const { return maxDepth_; }
    bool push() {
        if (stack_.size() == maxDepth_) return false;
        stack_.back().settleKind();  // the reference analyses the matrix it copies
        stack_.push_back(stack_.back());
        return true;
    }
    bool pop() {
        if (stack_.size() == 1) return false;
        stack_.pop_back();
        return true;
    }

private:
    std::size_t maxDepth_;
    std::vector<StackMatrix> stack_;
};

// GL's initial lighting state: light 0 alone has a white diffuse and specular colour.
inline glrenderer::LightingState defaultLighting() {
    glrenderer::LightingState l;
    l.lights[0].diffuse = l.lights[0].specular = {1, 1, 1, 1};
    return l;
}

// Fog's parameters as GL keeps them (issue 16); the pipeline's DrawState::fog is formed from
// them (fog_state.h).
struct FogParameters {
    bool enabled = false;
    GLenum mode = GL_EXP;
    float density = 1.0f, start = 0.0f, end = 1.0f, index = 0.0f;
    glm::vec4 color{0.0f};  // clamped, as set
};

// The per-fragment operations' parameters as GL keeps them for glGet (issue 16); the
// pipeline's DrawState::fragmentOps is formed from them (fragment_ops.cpp).
struct FragmentOpsParameters {
    GLenum alphaFunc = GL_ALWAYS;
    float alphaRef = 0.0f;  // clamped, as set
    GLenum stencilFunc = GL_ALWAYS;
    GLint stencilRef = 0;                                     // as given
    GLuint stencilValueMask = 0xFF, stencilWriteMask = 0xFF;  // the reference starts at its 8 bits
    GLenum stencilFail = GL_KEEP, stencilDepthFail = GL_KEEP, stencilDepthPass = GL_KEEP;
    GLint clearStencil = 0;
    GLenum blendSrc = GL_ONE, blendDst = GL_ZERO;
    GLenum logicOp = GL_COPY;
    bool indexLogicOp = false;  // accepted; an RGBA buffer has no indices
    std::array<bool, 4> colorMask{true, true, true, true};
};

struct Context::State {
    State(int width, int height) : framebuffer(width, height), pipeline(framebuffer) {
        draw.edit().viewport = {0, 0, width, height};
        draw.edit().fragmentOps.scissor = {false, 0, 0, width, height};
    }

    glrenderer::Framebuffer framebuffer;
    glrenderer::Pipeline pipeline;
    GLenum error = GL_NO_ERROR;

    // glBegin/glEnd assembly: the vertices go straight to the pipeline.
    bool insideBeginEnd = false;
    glm::vec4 color{1, 1, 1, 1};        // as given, as glGet reports it
    glm::vec4 vertexColor{1, 1, 1, 1};  // clamped to [0, 1]: what vertices carry
    glm::vec3 normal{0, 0, 1};
    glm::vec4 texCoord{0, 0, 0, 1};
    bool edgeFlag = true;

    // Matrices; the combined projection * modelview is recomputed when either changes
    // (updateModelviewProjection).
    MatrixStack modelview{32}, projection{32}, texture{10};
    GLenum matrixMode = GL_MODELVIEW;
    Matrix modelviewProjection = kIdentity;
    bool modelviewProjectionStale = false;
    // glClipPlane's equations in eye space; their clip-space planes (draw.clipPlanes) follow the
    // projection, again at the next glBegin once it changed.
    std::array<glm::vec4, 8> eyeClipPlanes{};
    bool clipPlanesStale = false;
    Evaluators evaluators;

    // Fixed-function state, kept as GL values where glGet returns them.
    TrackedDrawState draw;
    GLenum cullFaceMode = GL_BACK;
    GLenum frontFace = GL_CCW;
    GLenum depthFunc = GL_LESS;
    GLenum shadeModel = GL_SMOOTH;
    GLenum polygonModeFront = GL_FILL, polygonModeBack = GL_FILL;
    std::vector<GLenum> otherEnabled{GL_DITHER};  // accepted capabilities that change nothing here
    std::map<GLenum, GLenum> hints{{GL_PERSPECTIVE_CORRECTION_HINT, GL_DONT_CARE},
                                   {GL_POINT_SMOOTH_HINT, GL_DONT_CARE},
                                   {GL_LINE_SMOOTH_HINT, GL_DONT_CARE},
                                   {GL_POLYGON_SMOOTH_HINT, GL_DONT_CARE},
                                   {GL_FOG_HINT, GL_DONT_CARE}};
    glm::vec4 clearColor{0, 0, 0, 0};
    double clearDepth = 1.0;
    BufferState buffers;
    PixelStoreModes pack, unpack;  // glPixelStore
    PixelModes pixelModes;         // glPixelTransfer, glPixelZoom
    PixelMaps pixelMaps;           // glPixelMap
    // glDrawPixels' and glCopyPixels' depth, stencil and index values, reused from call to call.
    std::vector<std::uint32_t> pixelValues;
    TextureUnit textures;  // (issue 16)
    DisplayLists lists;
    ClientArrays arrays;
    AttribStack attribStack, clientAttribStack;

    // Lighting: the state as set, and as prepared for lighting vertices (again after any state
    // change, which ends the batch: see endBatch).
    glrenderer::LightingState lighting = defaultLighting();
    bool lightingEnabled = false;
    bool colorMaterialEnabled = false;
    GLenum colorMaterialFace = GL_FRONT_AND_BACK, colorMaterialMode = GL_AMBIENT_AND_DIFFUSE;
    glrenderer::VertexLighting vertexLighting;
    bool lightingStale = true;
    // The pipeline's copy of vertexLighting is out of date (a raster position may have made a
    // new vertexLighting without handing it to the pipeline).
    bool pipelineLightingStale = true;
    // glMaterial came inside the open glBegin/glEnd: its vertices are lit as they come.
    bool lightingOnProgramThread = false;

    FogParameters fog;                  // (issue 16)
    FragmentOpsParameters fragmentOps;  // (issue 16)

    // What the reference does when it validates state before a draw or a read: settle the
    // kinds of the current matrices and form their product.
    void updateModelviewProjection() {
        if (!modelviewProjectionStale) return;
        modelview.top().settleKind();
        projection.top().settleKind();
        modelviewProjection = combine(projection.top(), modelview.top());
        modelviewProjectionStale = false;
        pipeline.setTransform({modelviewProjection, modelview.top().matrix()});
    }

    // The current raster position (glRasterPos, moved by glBitmap) in window coordinates, and
    // what it took from the current attributes when it was last set.
    glm::vec4 rasterPosition{0, 0, 0, 1};
    glm::vec4 rasterColor{1, 1, 1, 1};
    glm::vec4 rasterTexCoord{0, 0, 0, 1};
    float rasterDistance = 0;

    // glRenderMode; in GL_SELECT, draws make hit records in the program's buffer instead of pixels,
    // in GL_FEEDBACK feedback tokens.
    GLenum renderMode = GL_RENDER;
    Selection selection;
    Feedback feedback;  // GL_FEEDBACK
    bool rasterValid = true;
    BitmapCache bitmapCache;

    MatrixStack& currentStack() {
        return matrixMode == GL_PROJECTION ? projection : matrixMode == GL_TEXTURE ? texture : modelview;
    }
};

// The context that receives gl* calls on this thread, or nullptr. Inline: every glVertex and
// glColor asks for it.
extern constinit thread_local Context* currentContext;
inline Context::State* currentState() { return currentContext ? &currentContext->state() : nullptr; }

// Draws the bitmaps the cache holds, with the state in force now: before any draw, clear, flush
// or read, as the reference does.
void drawCachedBitmaps(Context::State& state);

// Records `error` unless one is pending (the first error wins until glGetError reads it).
void setError(Context::State& state, GLenum error);

}  // namespace mygl
