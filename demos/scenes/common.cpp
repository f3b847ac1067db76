#include <glad/gl.h>

#include "scene.h"

namespace scenes {

void resetState(int width, int height) {
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glShadeModel(GL_SMOOTH);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void beginFrame(int width, int height, bool depthTest, bool cullBack) {
    resetState(width, height);
    glClearColor(0.08f, 0.08f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (depthTest) glEnable(GL_DEPTH_TEST);
    if (cullBack) glEnable(GL_CULL_FACE);
}

void pixelOrtho(int width, int height) {
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, width, 0.0, height, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
}

std::vector<std::uint32_t> readDepth(int width, int height) {
    std::vector<std::uint32_t> depth(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
    return depth;
}

void drawCube(const float (*faceColors)[3], bool oneColor) {
    // Faces wound counter-clockwise seen from outside.
    static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; ++f) {
        const float* c = faceColors[oneColor ? 0 : f];
        glColor3f(c[0], c[1], c[2]);
        for (int corner : faces[f]) glVertex3fv(corners[corner]);
    }
    glEnd();
}

}  // namespace scenes
