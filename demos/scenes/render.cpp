#include "render.h"

#include <glad/gl.h>
#include <reference/osmesa_context.h>

namespace scenes {
namespace {

// glEnable/glDisable/glPolygonMode wrapped so that the forced state holds whatever the scene
// says, as the course's keys overrode its scenes.
PFNGLENABLEPROC sceneEnable = nullptr;
PFNGLDISABLEPROC sceneDisable = nullptr;
PFNGLPOLYGONMODEPROC scenePolygonMode = nullptr;
Overrides active;

bool isForced(GLenum cap) {
    return (cap == GL_CULL_FACE && active.culling) || (cap == GL_DEPTH_TEST && active.depthTest);
}
void GLAD_API_PTR enableUnlessForced(GLenum cap) {
    if (!isForced(cap)) sceneEnable(cap);
}
void GLAD_API_PTR disableUnlessForced(GLenum cap) {
    if (!isForced(cap)) sceneDisable(cap);
}
void GLAD_API_PTR polygonModeUnlessForced(GLenum face, GLenum mode) {
    scenePolygonMode(face, active.wireframe ? GL_LINE : mode);
}


}  // namespace

std::optional<Backend> parseBackend(std::string_view name) {
    if (name == "mygl") return Backend::MyGL;
    if (name == "osmesa") return Backend::OSMesa;
    return std::nullopt;
}

void applyOverrides(const Overrides& overrides) {
    active = overrides;
    sceneEnable = glad_glEnable;
    sceneDisable = glad_glDisable;
    scenePolygonMode = glad_glPolygonMode;
    if (overrides.culling) (*overrides.culling ? sceneEnable : sceneDisable)(GL_CULL_FACE);
    if (overrides.depthTest) (*overrides.depthTest ? sceneEnable : sceneDisable)(GL_DEPTH_TEST);
    if (overrides.wireframe) scenePolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glad_glEnable = enableUnlessForced;
    glad_glDisable = disableUnlessForced;
    glad_glPolygonMode = polygonModeUnlessForced;
}

Frame render(Backend backend, const Scene& scene, int width, int height, int frame, const Overrides& overrides) {
    Frame result;
    result.image.width = width;
    result.image.height = height;
    if (backend == Backend::MyGL) {
        mygl::Context context(width, height);
        context.makeCurrent();
        applyOverrides(overrides);
        scene.draw(width, height, frame);
        result.image.rgba = context.readPixels();
        result.depth = readDepth(width, height);
        result.stats = context.stats();
    } else {
        reference::OsmesaContext context(width, height);
        context.makeCurrent();
        applyOverrides(overrides);
        scene.draw(width, height, frame);
        result.image.rgba = context.readPixels();
        result.depth = readDepth(width, height);
    }
    return result;
}

}  // namespace scenes
