#pragma once
// Renders a scene on either backend and hands back the frame, for the demo and the tests.
#include <mygl/context.h>
#include <reference/image.h>

#include <cstdint>
#include <optional>
#include <vector>
#include <string_view>

#include "scene.h"

namespace scenes {

enum class Backend { MyGL, OSMesa };
std::optional<Backend> parseBackend(std::string_view name);

struct Frame {
    reference::Image image;
    std::vector<std::uint32_t> depth;  // glReadPixels(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT), bottom row first
    mygl::Stats stats;                 // MyGL's counters; zero for OSMesa
};

// Overrides what a scene asks for, as the course's keys did (B toggles culling).
struct Overrides {
    std::optional<bool> culling;    // force GL_CULL_FACE on (back faces) or off
    std::optional<bool> depthTest;  // force GL_DEPTH_TEST on or off
    bool wireframe = false;         // force glPolygonMode(GL_FRONT_AND_BACK, GL_LINE)
    bool orthographic = false;      // replace the scene's perspective by an orthographic view
};

// Wraps the loaded GL table so that the overrides hold whatever a scene then asks for.
void applyOverrides(const Overrides& overrides);

// Creates a context of the backend, makes it current (loading the GL table), draws, reads back.
// `methods` choose how MyGL rasterizes (OSMesa ignores them).
Frame render(Backend backend, const Scene& scene, int width, int height, int frame, const Overrides& overrides = {},
             const glrenderer::Methods& methods = {});

}  // namespace scenes
