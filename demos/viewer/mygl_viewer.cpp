// mygl-viewer: the demo scenes in a window, as the course's framework showed them. F1..F9 pick
// a scene, B culling, W wireframe, D depth test, P orthographic, Space MyGL/OSMesa, C the diff
// view, arrows or a mouse drag animate; the title shows the backend, the culling state and the rasterized-triangle
// count.
#include <glad/gl.h>
#include <mygl/context.h>
#include <reference/compare.h>
#include <reference/osmesa_context.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "image_text.h"
#include "presenter.h"
#include "render.h"

namespace {

struct ViewerState {
    std::size_t scene = 4;  // the rotating cube
    bool osmesa = false, diff = false, wireframe = false, orthographic = false;
    std::optional<bool> culling, depthTest;  // unset: as the scene says
    int frame = 0;
    bool dirty = true;
};

std::string onOff(const std::optional<bool>& forced, const char* name) {
    return std::string(name) + (forced ? (*forced ? " on" : " off") : " (scene)");
}

}  // namespace

int main(int argc, char** argv) {
    const int width = 640, height = 480;
    ViewerState v;
    std::string screenshot;
    bool screenshotExact = false;  // --exact: no text overlay, so the window equals the frame
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--screenshot" && i + 1 < argc)
            screenshot = argv[++i];
        else if (arg == "--exact")
            screenshotExact = true;
        else if (arg == "--scene" && i + 1 < argc) {
            const std::string name = argv[++i];
            const auto& all = scenes::allScenes();
            for (std::size_t s = 0; s < all.size(); ++s)
                if (all[s].name == name) v.scene = s;
        } else {
            std::fprintf(stderr, "usage: mygl-viewer [--scene NAME] [--screenshot FILE.png] [--exact]\n");
            return 2;
        }
    }
    mygl::Context ours(width, height);
    reference::OsmesaContext theirs(width, height);
    Presenter window(width, height, "mygl-viewer");
    Presenter::Callbacks callbacks;
    callbacks.key = [&v, &window](unsigned char key, int, int, bool down) {
        if (!down) return;
        switch (key) {
        case 27: window.requestClose(); return;
        case 'b':
        case 'B': v.culling = !v.culling.value_or(false); break;
        case 'w':
        case 'W': v.wireframe = !v.wireframe; break;
        case 'd':
        case 'D': v.depthTest = !v.depthTest.value_or(false); break;
        case ' ': v.osmesa = !v.osmesa; break;
        case 'c':
        case 'C': v.diff = !v.diff; break;
        case 'p':
        case 'P': v.orthographic = !v.orthographic; break;
        default: return;
        }
        v.dirty = true;
    };
    callbacks.special = [&v](int key, int, int, bool down) {
        if (!down) return;
        if (key >= 1 && key <= 9 && static_cast<std::size_t>(key - 1) < scenes::allScenes().size())
            v.scene = static_cast<std::size_t>(key - 1);
        else if (key == 100 || key == 103)
            --v.frame;  // left, down
        else if (key == 101 || key == 102)
            ++v.frame;  // up, right
        v.dirty = true;
    };
    callbacks.motion = [&v, lastX = 0](int x, int, bool dragging) mutable {  // dragging animates, like the arrows
        if (!dragging) return;
        if (x / 8 != lastX / 8) {
            v.frame += x > lastX ? 1 : -1;
            v.dirty = true;
        }
        lastX = x;
    };
    window.setCallbacks(callbacks);
    while (!window.shouldClose()) {
        window.pollEvents();
        if (!v.dirty) {
            window.waitBriefly();
            continue;
        }
        v.dirty = false;
        const scenes::Scene& scene = scenes::allScenes()[v.scene];
        const scenes::Overrides overrides{v.culling, v.depthTest, v.wireframe, v.orthographic};
        auto draw = [&](bool onOsmesa) {
            if (onOsmesa)
                theirs.makeCurrent();
            else
                ours.makeCurrent();
            scenes::applyOverrides(overrides);
            scene.draw(width, height, v.frame);
            return reference::Image{width, height, onOsmesa ? theirs.readPixels() : ours.readPixels()};
        };
        const reference::Image mine = draw(false);
        const unsigned long long triangles = ours.stats().rasterized;
        const bool cullingOn = glIsEnabled(GL_CULL_FACE);  // as the frame was drawn, overrides included
        reference::Image shown = v.osmesa ? draw(true) : mine;
        std::string extra;
        if (v.diff) {
            const reference::Image other = draw(!v.osmesa);
            const reference::Comparison c = reference::compareImages(mine, v.osmesa ? shown : other);
            shown = reference::diffImage(mine, v.osmesa ? shown : other);
            extra = " | diff: " + reference::toString(c);
        }
        const std::string status = std::string(v.osmesa ? "OSMesa" : "MyGL") + " | " + scene.name + " | " +
                                   onOff(v.culling, "culling") + " | " + onOff(v.depthTest, "depth") +
                                   (v.wireframe ? " | wireframe" : "") + (v.orthographic ? " | orthographic" : "");
        const std::string counts = std::string(cullingOn ? "Culling... -> triangle: " : "No cull... -> triangle: ") +
                                   std::to_string(triangles) + extra;
        window.setTitle(status + " | " + counts);
        // The counts on the top-left corner, doubled in size, as the course printed them.
        if (!screenshotExact) glut::drawText(shown, 8, 8, status + "\n" + counts, {255, 255, 0, 255}, 2);
        window.present(shown);
        if (!screenshot.empty()) {
            reference::writePng(screenshot, window.screenshot());
            return 0;
        }
    }
    return 0;
}
