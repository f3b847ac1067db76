// What glPushAttrib and glPushClientAttrib save of each attribute group (GL 1.1's state tables),
// over the state MyGL has. Groups MyGL has no state of yet (GL_ACCUM_BUFFER_BIT) save nothing.
#include <tuple>

#include "attrib_stack.h"
#include "context_state.h"

namespace mygl {
namespace {

using State = Context::State;

// Saves the fields `Select(state)` ties together; the restore assigns them back.
template <auto Select>
RestoreGroup saveFields(const State& state) {
    auto saved = std::apply([](const auto&... field) { return std::make_tuple(field...); }, Select(state));
    return [saved](State& s) { Select(s) = saved; };
}

constexpr GLenum kEnableCapabilities[] = {
    GL_ALPHA_TEST, GL_BLEND, GL_COLOR_MATERIAL, GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_FOG, GL_LIGHTING,
    GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7, GL_LINE_SMOOTH,
    GL_LINE_STIPPLE, GL_NORMALIZE, GL_POINT_SMOOTH, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_TEXTURE_1D,
    GL_TEXTURE_2D, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_CLIP_PLANE0, GL_CLIP_PLANE1, GL_CLIP_PLANE2, GL_CLIP_PLANE3, GL_CLIP_PLANE4, GL_CLIP_PLANE5,
    GL_CLIP_PLANE0 + 6, GL_CLIP_PLANE0 + 7,
    GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX,
    GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_AUTO_NORMAL,
};
constexpr GLenum kColorBufferCapabilities[] = {GL_ALPHA_TEST, GL_BLEND, GL_DITHER};
constexpr GLenum kDepthBufferCapabilities[] = {GL_DEPTH_TEST};
constexpr GLenum kFogCapabilities[] = {GL_FOG};
constexpr GLenum kLightingCapabilities[] = {GL_COLOR_MATERIAL, GL_LIGHTING, GL_LIGHT0, GL_LIGHT1, GL_LIGHT2,
                                            GL_LIGHT3,         GL_LIGHT4,   GL_LIGHT5, GL_LIGHT6, GL_LIGHT7};
constexpr GLenum kLineCapabilities[] = {GL_LINE_SMOOTH, GL_LINE_STIPPLE};
constexpr GLenum kPointCapabilities[] = {GL_POINT_SMOOTH};
constexpr GLenum kPolygonCapabilities[] = {GL_CULL_FACE,          GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
                                           GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,      GL_POLYGON_STIPPLE};
constexpr GLenum kScissorCapabilities[] = {GL_SCISSOR_TEST};
constexpr GLenum kStencilCapabilities[] = {GL_STENCIL_TEST};
constexpr GLenum kTextureCapabilities[] = {GL_TEXTURE_1D,    GL_TEXTURE_2D,    GL_TEXTURE_GEN_S,
                                           GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
constexpr GLenum kEvalCapabilities[] = {
    GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX,
    GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_AUTO_NORMAL,
};
constexpr GLenum kTransformCapabilities[] = {GL_NORMALIZE,   GL_CLIP_PLANE0,     GL_CLIP_PLANE1,     GL_CLIP_PLANE2,
                                             GL_CLIP_PLANE3, GL_CLIP_PLANE4,     GL_CLIP_PLANE5,     GL_CLIP_PLANE0 + 6,
                                             GL_CLIP_PLANE0 + 7};

const AttribGroup kServerGroups[] = {
    {GL_CURRENT_BIT, {}, saveFields<[](auto& s) {
         return std::tie(s.color, s.vertexColor, s.normal, s.texCoord, s.edgeFlag, s.rasterPosition, s.rasterColor,
                         s.rasterTexCoord, s.rasterDistance, s.rasterValid);
     }>},
    {GL_ENABLE_BIT, kEnableCapabilities, nullptr},
    {GL_COLOR_BUFFER_BIT, kColorBufferCapabilities, saveFields<[](auto& s) { return std::tie(s.clearColor); }>},
    {GL_DEPTH_BUFFER_BIT, kDepthBufferCapabilities, saveFields<[](auto& s) {
         return std::tie(s.depthFunc, s.draw.depthFunc, s.draw.depthWrite, s.clearDepth);
     }>},
    {GL_FOG_BIT, kFogCapabilities, saveFields<[](auto& s) { return std::tie(s.fog, s.draw.fog); }>},
    {GL_EVAL_BIT, kEvalCapabilities, saveFields<[](auto& s) {
         auto& e = s.evaluators;
         return std::tie(e.grid1un, e.grid1u1, e.grid1u2, e.grid1du, e.grid2un, e.grid2u1, e.grid2u2, e.grid2du,
                         e.grid2vn, e.grid2v1, e.grid2v2, e.grid2dv);
     }>},
    {GL_LIGHTING_BIT, kLightingCapabilities, saveFields<[](auto& s) {
         // (GL_NORMALIZE and GL_RESCALE_NORMAL, kept in the lighting state, belong to other groups.)
         auto& l = s.lighting;
         return std::tie(s.shadeModel, s.draw.shadeModel, l.lights, l.modelAmbient, l.localViewer, l.twoSide,
                         l.separateSpecular, l.materials, l.colorMaterial, s.colorMaterialFace, s.colorMaterialMode);
     }>},
    {GL_LINE_BIT, kLineCapabilities, saveFields<[](auto& s) { return std::tie(s.draw.lineWidth); }>},
    {GL_POINT_BIT, kPointCapabilities, saveFields<[](auto& s) { return std::tie(s.draw.pointSize); }>},
    {GL_POLYGON_BIT, kPolygonCapabilities, saveFields<[](auto& s) {
         return std::tie(s.cullFaceMode, s.draw.cullFace, s.frontFace, s.draw.frontFaceCCW, s.polygonModeFront,
                         s.draw.polygonFront, s.polygonModeBack, s.draw.polygonBack, s.draw.polygonOffset.factor,
                         s.draw.polygonOffset.units);
     }>},
    {GL_SCISSOR_BIT, kScissorCapabilities, nullptr},
    {GL_STENCIL_BUFFER_BIT, kStencilCapabilities, nullptr},
    // (The bound textures' own parameters are not saved yet.)
    {GL_TEXTURE_BIT, kTextureCapabilities, saveFields<[](auto& s) {
         auto& t = s.textures;
         return std::tie(t.bound1D, t.bound2D, t.envMode, t.envColor, t.gen.mode, t.gen.objectPlane, t.gen.eyePlane,
                         t.genMode);
     }>},
    {GL_TRANSFORM_BIT, kTransformCapabilities, saveFields<[](auto& s) { return std::tie(s.matrixMode, s.eyeClipPlanes); }>},
    {GL_VIEWPORT_BIT, {}, saveFields<[](auto& s) {
         return std::tie(s.draw.viewport, s.draw.depthNear, s.draw.depthFar);
     }>},
    {GL_HINT_BIT, {}, saveFields<[](auto& s) { return std::tie(s.hints); }>},
    {GL_LIST_BIT, {}, saveFields<[](auto& s) { return std::tie(s.lists.base); }>},
    {GL_PIXEL_MODE_BIT, {}, saveFields<[](auto& s) { return std::tie(s.pixelModes); }>},
};

const AttribGroup kClientGroups[] = {
    {GL_CLIENT_PIXEL_STORE_BIT, {}, saveFields<[](auto& s) { return std::tie(s.pack, s.unpack); }>},
    {GL_CLIENT_VERTEX_ARRAY_BIT, {}, saveFields<[](auto& s) { return std::tie(s.arrays); }>},
};

}  // namespace

std::span<const AttribGroup> serverAttribGroups() { return kServerGroups; }
std::span<const AttribGroup> clientAttribGroups() { return kClientGroups; }

}  // namespace mygl
