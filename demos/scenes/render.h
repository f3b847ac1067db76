#pragma once
// Renders a scene on either backend and hands back the frame, for the demo and the tests.
#include <mygl/context.h>
#include <reference/image.h>

#include <optional>
#include <string_view>

#include "scene.h"

namespace scenes {

enum class Backend { MyGL, OSMesa };
std::optional<Backend> parseBackend(std::string_view name);

struct Frame {
    reference::Image image;
    mygl::Stats stats;  // MyGL's counters; zero for OSMesa
};

// Creates a context of the backend, makes it current (loading the GL table), draws, reads back.
Frame render(Backend backend, const Scene& scene, int width, int height, int frame);

}  // namespace scenes
