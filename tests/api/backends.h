#pragma once
// Runs the same GL calls on MyGL and on OSMesa, each through the loaded GL table.
#include <glad/gl.h>
#include <mygl/context.h>
#include <reference/osmesa_context.h>

#include <functional>

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

}  // namespace testing_support
