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
PFNGLMATRIXMODEPROC sceneMatrixMode = nullptr;
PFNGLFRUSTUMPROC sceneFrustum = nullptr;
PFNGLMULTMATRIXDPROC sceneMultMatrixd = nullptr;
GLenum matrixMode = GL_MODELVIEW;
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
void GLAD_API_PTR trackMatrixMode(GLenum mode) {
    matrixMode = mode;
    sceneMatrixMode(mode);
}
// A perspective projection (glFrustum, or gluPerspective's glMultMatrixd with w = -z) becomes an
// orthographic one of about the same extent at the scenes' viewing distance.
void orthographicInstead() { glOrtho(-3.2, 3.2, -2.4, 2.4, -100.0, 100.0); }
void GLAD_API_PTR frustumOrOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
    if (active.orthographic)
        orthographicInstead();
    else
        sceneFrustum(l, r, b, t, n, f);
}
void GLAD_API_PTR multMatrixOrOrtho(const GLdouble* m) {
    if (active.orthographic && matrixMode == GL_PROJECTION && m && m[11] == -1.0)
        orthographicInstead();
    else
        sceneMultMatrixd(m);
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
    sceneMatrixMode = glad_glMatrixMode;
    sceneFrustum = glad_glFrustum;
    sceneMultMatrixd = glad_glMultMatrixd;
    matrixMode = GL_MODELVIEW;
    if (overrides.culling) (*overrides.culling ? sceneEnable : sceneDisable)(GL_CULL_FACE);
    if (overrides.depthTest) (*overrides.depthTest ? sceneEnable : sceneDisable)(GL_DEPTH_TEST);
    if (overrides.wireframe) scenePolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glad_glEnable = enableUnlessForced;
    glad_glDisable = disableUnlessForced;
    glad_glPolygonMode = polygonModeUnlessForced;
    glad_glMatrixMode = trackMatrixMode;
    glad_glFrustum = frustumOrOrtho;
    glad_glMultMatrixd = multMatrixOrOrtho;
}

Frame render(Backend backend, const Scene& scene, int width, int height, int frame, const Overrides& overrides,
             const glrenderer::Methods& methods) {
    Frame result;
    result.image.width = width;
    result.image.height = height;
    if (backend == Backend::MyGL) {
        mygl::Context context(width, height);
        context.setMethods(methods);
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
