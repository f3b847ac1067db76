#include "render.h"

#include <reference/osmesa_context.h>

namespace scenes {

std::optional<Backend> parseBackend(std::string_view name) {
    if (name == "mygl") return Backend::MyGL;
    if (name == "osmesa") return Backend::OSMesa;
    return std::nullopt;
}

Frame render(Backend backend, const Scene& scene, int width, int height, int frame) {
    Frame result;
    result.image.width = width;
    result.image.height = height;
    if (backend == Backend::MyGL) {
        mygl::Context context(width, height);
        context.makeCurrent();
        scene.draw(width, height, frame);
        result.image.rgba = context.readPixels();
        result.stats = context.stats();
    } else {
        reference::OsmesaContext context(width, height);
        context.makeCurrent();
        scene.draw(width, height, frame);
        result.image.rgba = context.readPixels();
    }
    return result;
}

}  // namespace scenes
