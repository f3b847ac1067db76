#pragma once
// Runs the same GL calls on MyGL and on OSMesa, each through the loaded GL table.
#include <glad/gl.h>
#include <mygl/context.h>
#include <reference/osmesa_context.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace testing_support {

template <class Result>
struct BothResults {
    Result mygl;
    Result osmesa;
};

template <class Result>
BothResults<Result> onBothBackends(const std::function<Result()>& calls, int width = 16, int height = 16) {
    BothResults<Result> results;
    {
        mygl::Context context(width, height);
        context.makeCurrent();
        results.mygl = calls();
    }
    {
        reference::OsmesaContext context(width, height);
        context.makeCurrent();
        results.osmesa = calls();
    }
    return results;
}

// Clears colour and depth, enables the depth test, and looks down -z from `distance` through a
// 4:3 frustum (near 1, far 30): the view the display-list and vertex-array tests draw in.
inline void clearedPerspectiveView(float distance) {
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -distance);
}

// Clears colour to `clear`, depth to `depth` and stencil to `stencil`, and looks at
// [0, width] x [0, height] orthographically with depth in [-1, 1]: the view the pixel and
// fragment-operation tests draw in.
inline void clearedOrthoView(int width, int height, const GLfloat (&clear)[4], GLdouble depth, GLint stencil) {
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    glClearDepth(depth);
    glClearStencil(stencil);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, width, 0, height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

// The colour (RGBA8) and 24-bit depth (as GL_UNSIGNED_INT) of every pixel, after glFinish.
struct Frame {
    std::vector<GLubyte> color;
    std::vector<GLuint> depth;
    bool operator==(const Frame&) const = default;
};

inline Frame readFrame(int width, int height) {
    Frame frame{std::vector<GLubyte>(static_cast<std::size_t>(width * height) * 4),
                std::vector<GLuint>(static_cast<std::size_t>(width * height))};
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, frame.color.data());
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, frame.depth.data());
    return frame;
}

// Where two walks of values (queries and errors, in call order) first differ, for a failure
// message: "index: ours vs theirs", or "" if they are equal.
inline std::string firstDifference(const std::vector<double>& ours, const std::vector<double>& theirs) {
    const std::size_t n = std::min(ours.size(), theirs.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!(ours[i] == theirs[i]) && !(ours[i] != ours[i] && theirs[i] != theirs[i]))
            return std::to_string(i) + ": " + std::to_string(ours[i]) + " vs " + std::to_string(theirs[i]);
    }
    return ours.size() == theirs.size()
               ? ""
               : "sizes " + std::to_string(ours.size()) + " vs " + std::to_string(theirs.size());
}

}  // namespace testing_support
