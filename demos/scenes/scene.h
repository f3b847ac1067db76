#pragma once
// Scenes in plain GL 1.x, called through the GL loader table (<glad/gl.h>), so that each runs
// unchanged on whichever backend is current. Each sets its own viewport, matrices and state.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace scenes {

struct Scene {
    std::string name;
    std::string description;
    void (*draw)(int width, int height, int frame);
};

std::span<const Scene> allScenes();
const Scene* findScene(std::string_view name);

// Clears to transparent black and puts back GL's defaults for everything the scenes change:
// depth test and culling off, smooth fill, identity matrices, the viewport on the window.
void resetState(int width, int height);

// resetState with the scenes' background, then the depth test and back-face culling as asked.
void beginFrame(int width, int height, bool depthTest, bool cullBack);

// A projection in window pixels (glOrtho(0, width, 0, height, -1, 1)), modelview current.
void pixelOrtho(int width, int height);

// The depth buffer through the loaded GL table, as GL_UNSIGNED_INT (24 bits scaled to 32).
std::vector<std::uint32_t> readDepth(int width, int height);

// One cube of side 2 centered at the origin, each face its own color (or one color for all).
void drawCube(const float (*faceColors)[3], bool oneColor = false);

}  // namespace scenes
