#include "render.h"

#include <glad/gl.h>
#include <reference/osmesa_context.h>

namespace scenes {
namespace {

// glEnable/glDisable wrapped so that GL_CULL_FACE keeps the forced value whatever the scene says.
PFNGLENABLEPROC sceneEnable = nullptr;
PFNGLDISABLEPROC sceneDisable = nullptr;
bool forcedCulling = false;

void GLAD_API_PTR enableExceptCulling(GLenum cap) {
    if (cap != GL_CULL_FACE) sceneEnable(cap);
}
void GLAD_API_PTR disableExceptCulling(GLenum cap) {
    if (cap != GL_CULL_FACE) sceneDisable(cap);
}

void applyOverrides(const Overrides& overrides) {
    if (!overrides.culling) return;
    forcedCulling = *overrides.culling;
    sceneEnable = glad_glEnable;
    sceneDisable = glad_glDisable;
    (forcedCulling ? sceneEnable : sceneDisable)(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glad_glEnable = enableExceptCulling;
    glad_glDisable = disableExceptCulling;
}

}  // namespace

std::optional<Backend> parseBackend(std::string_view name) {
    if (name == "mygl") return Backend::MyGL;
    if (name == "osmesa") return Backend::OSMesa;
    return std::nullopt;
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
