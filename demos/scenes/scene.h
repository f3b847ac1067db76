#pragma once
// Scenes in plain GL 1.x, called through the GL loader table (<glad/gl.h>), so that each runs
// unchanged on whichever backend is current. Each sets its own viewport, matrices and state.
#include <span>
#include <string>
#include <string_view>

namespace scenes {

struct Scene {
    std::string name;
    std::string description;
    void (*draw)(int width, int height, int frame);
};

std::span<const Scene> allScenes();
const Scene* findScene(std::string_view name);

// Resets the state every scene relies on: clear color, depth, culling, shading, matrices.
void beginFrame(int width, int height, bool depthTest, bool cullBack);

// One cube of side 2 centered at the origin, each face its own color (or one color for all).
void drawCube(const float (*faceColors)[3], bool oneColor = false);

}  // namespace scenes
