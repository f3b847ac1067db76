// What glPushAttrib and glPushClientAttrib save of each attribute group (GL 1.1's state tables),
// over the state MyGL has.
#include <tuple>

#include "attrib_stack.h"
#include "context_state.h"
#include "textures.h"

namespace mygl {
namespace {

using State = Context::State;

// The draw state in a group's fields: changed when a restore assigns them.
glrenderer::DrawState& drawOf(State& s) { return s.draw.edit(); }
const glrenderer::DrawState& drawOf(const State& s) { return *s.draw; }

// Saves the fields `Select(state)` ties together; the restore assigns them back.
template <auto Select>
RestoreGroup saveFields(const State& state) {
    auto saved = std::apply([](const auto&... field) { return std::make_tuple(field...); }, Select(state));
    return [saved](State& s) { Select(s) = saved; };
}

constexpr GLenum kEnableCapabilities[] = {
    GL_ALPHA_TEST,
    GL_BLEND,
    GL_COLOR_MATERIAL,
    GL_CULL_FACE,
    GL_DEPTH_TEST,
    GL_DITHER,
    GL_FOG,
    GL_LIGHTING,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_NORMALIZE,
    GL_POINT_SMOOTH,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_SCISSOR_TEST,
    GL_STENCIL_TEST,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
    GL_COLOR_LOGIC_OP,
    GL_INDEX_LOGIC_OP,
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
    GL_CLIP_PLANE0 + 6,
    GL_CLIP_PLANE0 + 7,
    GL_MAP1_COLOR_4,
    GL_MAP1_INDEX,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP2_COLOR_4,
    GL_MAP2_INDEX,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_AUTO_NORMAL,
};
constexpr GLenum kColorBufferCapabilities[] = {GL_ALPHA_TEST, GL_BLEND, GL_DITHER, GL_COLOR_LOGIC_OP,
                                               GL_INDEX_LOGIC_OP};
constexpr GLenum kDepthBufferCapabilities[] = {GL_DEPTH_TEST};
constexpr GLenum kFogCapabilities[] = {GL_FOG};
constexpr GLenum kLightingCapabilities[] = {GL_COLOR_MATERIAL, GL_LIGHTING, GL_LIGHT0, GL_LIGHT1, GL_LIGHT2,
                                            GL_LIGHT3,         GL_LIGHT4,   GL_LIGHT5, GL_LIGHT6, GL_LIGHT7};
constexpr GLenum kLineCapabilities[] = {GL_LINE_SMOOTH, GL_LINE_STIPPLE};
constexpr GLenum kPointCapabilities[] = {GL_POINT_SMOOTH};
constexpr GLenum kPolygonCapabilities[] = {GL_CULL_FACE,           GL_POLYGON_OFFSET_FILL,
                                           GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT,
                                           GL_POLYGON_SMOOTH,      GL_POLYGON_STIPPLE};
constexpr GLenum kScissorCapabilities[] = {GL_SCISSOR_TEST};
constexpr GLenum kStencilCapabilities[] = {GL_STENCIL_TEST};
constexpr GLenum kTextureCapabilities[] = {GL_TEXTURE_1D,    GL_TEXTURE_2D,    GL_TEXTURE_GEN_S,
                                           GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
constexpr GLenum kEvalCapabilities[] = {
    GL_MAP1_COLOR_4,         GL_MAP1_INDEX,           GL_MAP1_NORMAL,          GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,        GL_MAP2_COLOR_4,         GL_MAP2_INDEX,           GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,        GL_MAP2_VERTEX_4,        GL_AUTO_NORMAL,
};
constexpr GLenum kTransformCapabilities[] = {GL_NORMALIZE,   GL_CLIP_PLANE0,     GL_CLIP_PLANE1,
                                             GL_CLIP_PLANE2, GL_CLIP_PLANE3,     GL_CLIP_PLANE4,
                                             GL_CLIP_PLANE5, GL_CLIP_PLANE0 + 6, GL_CLIP_PLANE0 + 7};

// GL_TEXTURE_BIT: the unit's bindings, environment and texgen, and the parameters of the
// textures bound now (restored into those textures, if they still exist).
RestoreGroup saveTextures(const State& state) {
    const RestoreGroup unit = saveFields<[](auto& s) {
        auto& t = s.textures;
        return std::tie(t.bound1D, t.bound2D, t.envMode, t.envColor, t.gen.mode, t.gen.objectPlane, t.gen.eyePlane,
                        t.genMode);
    }>(state);
    struct Parameters {
        GLenum target;
        GLuint name;
        GLenum minFilter, magFilter, wrapS, wrapT;
        glm::vec4 borderColor;
        float priority;
    };
    std::vector<Parameters> saved;
    for (const GLenum target : {GLenum{GL_TEXTURE_1D}, GLenum{GL_TEXTURE_2D}}) {
        const TextureObject& t = boundTexture(state.textures, target);
        const GLuint name = target == GL_TEXTURE_1D ? state.textures.bound1D : state.textures.bound2D;
        saved.push_back({target, name, t.minFilter, t.magFilter, t.wrapS, t.wrapT, t.borderColor, t.priority});
    }
    return [unit, saved](State& s) {
        unit(s);
        for (const Parameters& p : saved) {
            TextureUnit& textures = s.textures;
            const auto found = textures.objects.find(p.name);
            TextureObject* t = p.name == 0 ? (p.target == GL_TEXTURE_1D ? &textures.default1D : &textures.default2D)
                               : found != textures.objects.end() ? &found->second
                                                                 : nullptr;
            if (!t) continue;
            t->minFilter = p.minFilter, t->magFilter = p.magFilter, t->wrapS = p.wrapS, t->wrapT = p.wrapT;
            t->borderColor = p.borderColor, t->priority = p.priority;
        }
    };
}

const AttribGroup kServerGroups[] = {
    {GL_CURRENT_BIT, {}, saveFields<[](auto& s) {
         return std::tie(s.color, s.vertexColor, s.normal, s.texCoord, s.edgeFlag, s.rasterPosition, s.rasterColor,
                         s.rasterTexCoord, s.rasterDistance, s.rasterValid, s.buffers.currentIndex);
     }>},
    {GL_ENABLE_BIT, kEnableCapabilities, nullptr},
    {GL_COLOR_BUFFER_BIT, kColorBufferCapabilities, saveFields<[](auto& s) {
         auto& p = s.fragmentOps;
         auto& o = drawOf(s).fragmentOps;
         return std::tie(s.clearColor, s.buffers.drawBuffer, s.buffers.clearIndex, s.buffers.indexMask, p.alphaFunc,
                         p.alphaRef, p.blendSrc, p.blendDst, p.logicOp, p.colorMask, o.alphaFunc, o.alphaRef,
                         o.blendSrc, o.blendDst, o.logicOp, o.colorMask);
     }>},
    {GL_ACCUM_BUFFER_BIT, {}, saveFields<[](auto& s) { return std::tie(s.buffers.accumClear); }>},
    {GL_PIXEL_MODE_BIT, {}, saveFields<[](auto& s) { return std::tie(s.buffers.readBuffer, s.pixelModes); }>},
    {GL_DEPTH_BUFFER_BIT, kDepthBufferCapabilities, saveFields<[](auto& s) {
         return std::tie(s.depthFunc, drawOf(s).depthFunc, drawOf(s).depthWrite, s.clearDepth);
     }>},
    {GL_FOG_BIT, kFogCapabilities, saveFields<[](auto& s) { return std::tie(s.fog, drawOf(s).fog); }>},
    {GL_EVAL_BIT, kEvalCapabilities, saveFields<[](auto& s) {
         auto& e = s.evaluators;
         return std::tie(e.grid1un, e.grid1u1, e.grid1u2, e.grid1du, e.grid2un, e.grid2u1, e.grid2u2, e.grid2du,
                         e.grid2vn, e.grid2v1, e.grid2v2, e.grid2dv);
     }>},
    {GL_LIGHTING_BIT, kLightingCapabilities, saveFields<[](auto& s) {
         // (GL_NORMALIZE and GL_RESCALE_NORMAL, kept in the lighting state, belong to other groups.)
         auto& l = s.lighting;
         return std::tie(s.shadeModel, drawOf(s).shadeModel, l.lights, l.modelAmbient, l.localViewer, l.twoSide,
                         l.separateSpecular, l.materials, l.colorMaterial, s.colorMaterialFace, s.colorMaterialMode);
     }>},
    {GL_LINE_BIT, kLineCapabilities, saveFields<[](auto& s) {
         return std::tie(drawOf(s).lineWidth, drawOf(s).lineStipple.pattern, drawOf(s).lineStipple.factor);
     }>},
    {GL_POLYGON_STIPPLE_BIT, {}, saveFields<[](auto& s) { return std::tie(drawOf(s).polygonStipple.pattern); }>},
    {GL_POINT_BIT, kPointCapabilities, saveFields<[](auto& s) { return std::tie(drawOf(s).pointSize); }>},
    {GL_POLYGON_BIT, kPolygonCapabilities, saveFields<[](auto& s) {
         return std::tie(s.cullFaceMode, drawOf(s).cullFace, s.frontFace, drawOf(s).frontFaceCCW, s.polygonModeFront,
                         drawOf(s).polygonFront, s.polygonModeBack, drawOf(s).polygonBack,
                         drawOf(s).polygonOffset.factor, drawOf(s).polygonOffset.units);
     }>},
    {GL_SCISSOR_BIT, kScissorCapabilities, saveFields<[](auto& s) { return std::tie(drawOf(s).fragmentOps.scissor); }>},
    {GL_STENCIL_BUFFER_BIT, kStencilCapabilities, saveFields<[](auto& s) {
         auto& p = s.fragmentOps;
         return std::tie(p.stencilFunc, p.stencilRef, p.stencilValueMask, p.stencilWriteMask, p.stencilFail,
                         p.stencilDepthFail, p.stencilDepthPass, p.clearStencil, drawOf(s).fragmentOps.stencil);
     }>},
    {GL_TEXTURE_BIT, kTextureCapabilities, saveTextures},
    {GL_TRANSFORM_BIT, kTransformCapabilities,
     saveFields<[](auto& s) { return std::tie(s.matrixMode, s.eyeClipPlanes); }>},
    {GL_VIEWPORT_BIT,
     {},
     saveFields<[](auto& s) { return std::tie(drawOf(s).viewport, drawOf(s).depthNear, drawOf(s).depthFar); }>},
    {GL_HINT_BIT, {}, saveFields<[](auto& s) { return std::tie(s.hints); }>},
    {GL_LIST_BIT, {}, saveFields<[](auto& s) { return std::tie(s.lists.base); }>},
};

const AttribGroup kClientGroups[] = {
    {GL_CLIENT_PIXEL_STORE_BIT, {}, saveFields<[](auto& s) { return std::tie(s.pack, s.unpack); }>},
    {GL_CLIENT_VERTEX_ARRAY_BIT, {}, saveFields<[](auto& s) { return std::tie(s.arrays); }>},
};

}  // namespace

std::span<const AttribGroup> serverAttribGroups() { return kServerGroups; }
std::span<const AttribGroup> clientAttribGroups() { return kClientGroups; }

}  // namespace mygl
