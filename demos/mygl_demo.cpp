// mygl-demo: renders the demo scenes headless on MyGL, OSMesa or both, writes PNGs and, with
// both, a diff image and a comparison row per scene.
#include <reference/compare.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render.h"
#include "stability.h"

namespace {

struct Options {
    std::string scene = "all";
    std::string backend = "both";
    int width = 320, height = 240, frame = 0;
    std::string out = "out";
    bool list = false;
    bool stats = false;
    bool stability = false;
    glrenderer::Methods methods;
};

[[noreturn]] void usage(const std::string& error) {
    std::fprintf(stderr,
                 "mygl-demo: %s\n"
                 "usage: mygl-demo [--scene NAME|all] [--backend mygl|osmesa|both] [--size WxH]\n"
                 "                 [--frame N] [--out DIR] [--list] [--stats] [--stability]\n"
                 "                 [--method exact|exact-per-pixel|scanline|bbox-float]\n",
                 error.c_str());
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage("missing value after " + arg);
            return argv[++i];
        };
        if (arg == "--scene")
            o.scene = value();
        else if (arg == "--backend")
            o.backend = value();
        else if (arg == "--out")
            o.out = value();
        else if (arg == "--frame")
            o.frame = std::atoi(value().c_str());
        else if (arg == "--list")
            o.list = true;
        else if (arg == "--stats")
            o.stats = true;
        else if (arg == "--stability")
            o.stability = true;
        else if (arg == "--method") {
            const std::string name = value();
            const auto method = glrenderer::parseRasterMethod(name);
            if (!method) usage("unknown method '" + name + "' (exact, exact-per-pixel, scanline, bbox-float)");
            o.methods.raster = *method;
        } else if (arg == "--size") {
            const std::string size = value();
            if (std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1 ||
                o.width > mygl::Context::kMaxSize || o.height > mygl::Context::kMaxSize)
                usage("bad --size '" + size + "' (expected WxH, e.g. 320x240)");
        } else
            usage("unknown argument '" + arg + "'");
    }
    if (o.backend != "both" && !scenes::parseBackend(o.backend)) usage("unknown backend '" + o.backend + "'");
    if (o.scene != "all" && !scenes::findScene(o.scene)) usage("unknown scene '" + o.scene + "' (see --list)");
    return o;
}

// The course's table: what the pipeline did with each scene, culling forced off and then on.
void printStats(const std::vector<const scenes::Scene*>& selected, const Options& o) {
    // tris + created = clipped + back + front + zero + rasterized
    std::printf("%-28s %-9s %5s %8s %8s %7s %7s %5s %10s %10s %10s\n", "scene", "culling", "tris", "created", "clipped",
                "back", "front", "zero", "rasterized", "fragments", "passed");
    for (const scenes::Scene* scene : selected) {
        for (bool culling : {false, true}) {
            const mygl::Stats s = scenes::render(scenes::Backend::MyGL, *scene, o.width, o.height, o.frame,
                                                 {culling, std::nullopt, false, false})
                                      .stats;
            std::printf("%-28s %-9s %5llu %8llu %8llu %7llu %7llu %5llu %10llu %10llu %10llu\n", scene->name.c_str(),
                        culling ? "cull=back" : "cull=off", static_cast<unsigned long long>(s.triangles),
                        static_cast<unsigned long long>(s.clipCreated), static_cast<unsigned long long>(s.clippedAway),
                        static_cast<unsigned long long>(s.culledBack), static_cast<unsigned long long>(s.culledFront),
                        static_cast<unsigned long long>(s.culledZeroArea),
                        static_cast<unsigned long long>(s.rasterized), static_cast<unsigned long long>(s.fragments),
                        static_cast<unsigned long long>(s.fragmentsPassed));
        }
    }
}

// Where each method holds and breaks against OSMesa (pixels differing by more than 1).
void printStability() {
    const auto methods = stability::allMethods();
    std::printf("| check |");
    for (const auto& m : methods) std::printf(" %s |", m.name.c_str());
    std::printf("\n|---|");
    for (std::size_t i = 0; i < methods.size(); ++i) std::printf("---|");
    std::printf("\n");
    for (const stability::Check& check : stability::allChecks()) {
        std::printf("| %s |", check.name.c_str());
        for (const auto& m : methods) {
            const stability::Outcome o = stability::run(check, m);
            if (o.holds)
                std::printf(" holds |");
            else
                std::printf(" breaks (%lld px) |", o.pixelsOver1);
        }
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parse(argc, argv);
    if (options.list) {
        for (const scenes::Scene& scene : scenes::allScenes())
            std::printf("%-28s %s\n", scene.name.c_str(), scene.description.c_str());
        return 0;
    }
    std::vector<const scenes::Scene*> selected;
    for (const scenes::Scene& scene : scenes::allScenes())
        if (options.scene == "all" || scene.name == options.scene) selected.push_back(&scene);
    if (options.stability) {
        printStability();
        return 0;
    }
    if (options.stats) {
        printStats(selected, options);
        return 0;
    }
    std::filesystem::create_directories(options.out);
    const bool both = options.backend == "both";
    if (both) {
        std::printf("MyGL method: %s\n", std::string(glrenderer::toString(options.methods.raster)).c_str());
        std::printf("%-28s %9s %9s %7s %4s\n", "scene", "pixels", "differing", ">1", "max");
    }
    for (const scenes::Scene* scene : selected) {
        const std::string base = options.out + "/" + scene->name;
        if (both || options.backend == "mygl") {
            const scenes::Frame ours = scenes::render(scenes::Backend::MyGL, *scene, options.width, options.height,
                                                      options.frame, {}, options.methods);
            reference::writePng(base + "-mygl.png", ours.image);
            if (both) {
                const scenes::Frame theirs =
                    scenes::render(scenes::Backend::OSMesa, *scene, options.width, options.height, options.frame);
                reference::writePng(base + "-osmesa.png", theirs.image);
                reference::writePng(base + "-diff.png", reference::diffImage(ours.image, theirs.image));
                const reference::Comparison c = reference::compareImages(ours.image, theirs.image);
                std::printf("%-28s %9lld %9lld %7lld %4d\n", scene->name.c_str(), c.pixels, c.differing,
                            c.differingMoreThan1, c.maxChannelDifference);
            }
        } else {
            reference::writePng(
                base + "-osmesa.png",
                scenes::render(scenes::Backend::OSMesa, *scene, options.width, options.height, options.frame).image);
        }
    }
    std::printf("images written to %s/\n", options.out.c_str());
    return 0;
}
