// mygl-bench: time per frame against pixels differing from OSMesa llvmpipe, for every MyGL
// method and the reference renderers, on the benchmark scenes. Writes a CSV, a markdown table
// and (through plot_bench.py) a chart. In-process variants alternate, each timing a frame after
// an untimed one of its own; variants that need their own environment (one llvmpipe thread,
// softpipe, MyGL with AVX2 kernels only) run in a child process of this program.
#include <glad/gl.h>
#include <reference/compare.h>
#include <reference/osmesa_context.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <malloc.h>
#include <unistd.h>

#include "render.h"

namespace {

using Clock = std::chrono::steady_clock;

const char* const kScenes[] = {
    "bench-torus",       "bench-fill",           "bench-cubes",      "bench-tiny",        "bench-gears",
    "bench-gears-lists", "bench-mesh",           "bench-lit-torus",  "bench-fog-terrain", "bench-fog-textured-terrain",
    "bench-particles",   "bench-textured-cubes", "bench-draw-pixels"};

struct Variant {
    std::string name;
    bool isReference;
    glrenderer::Methods methods;  // MyGL variants
    std::string environment;      // child-process variants: "NAME=value", empty = in-process
};

std::vector<Variant> variants() {
    using glrenderer::Interpolation;
    using glrenderer::RasterMethod;
    return {
        {"mygl exact", false, {RasterMethod::Exact, Interpolation::PerspectiveCorrect}, ""},
        {"mygl exact-per-pixel", false, {RasterMethod::ExactPerPixel, Interpolation::PerspectiveCorrect}, ""},
        {"mygl scanline", false, {RasterMethod::Scanline, Interpolation::PerspectiveCorrect}, ""},
        {"mygl bbox-float", false, {RasterMethod::BoundingBoxFloat, Interpolation::PerspectiveCorrect}, ""},
        {"mygl exact screen-linear", false, {RasterMethod::Exact, Interpolation::ScreenLinear}, ""},
        {"osmesa llvmpipe", true, {}, ""},
        {"osmesa llvmpipe 1 thread", true, {}, "LP_NUM_THREADS=1"},
        {"osmesa softpipe", true, {}, "GALLIUM_DRIVER=softpipe"},
        // How a CPU without AVX-512 runs the exact method (the same pixels).
        {"mygl exact avx2", false, {RasterMethod::Exact, Interpolation::PerspectiveCorrect}, "MYGL_KERNELS=avx2"},
    };
}

struct Timing {
    std::vector<double> ms;
    reference::Image frame;
    double median() const {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        return sorted[sorted.size() / 2];
    }
};

// One backend's context, kept for all repetitions of a scene.
class Target {
public:
    Target(const Variant& v, int width, int height) {
        if (v.isReference) {
            osmesa_ = std::make_unique<reference::OsmesaContext>(width, height);
        } else {
            mygl_ = std::make_unique<mygl::Context>(width, height);
            mygl_->setMethods(v.methods);
        }
    }
    // Draws one frame and returns the milliseconds until glFinish returned.
    double drawFrame(const scenes::Scene& scene, int width, int height) {
        if (mygl_)
            mygl_->makeCurrent();
        else
            osmesa_->makeCurrent();
        const auto start = Clock::now();
        scene.draw(width, height, 0);
        glFinish();
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    reference::Image frame(int width, int height) {
        return {width, height, mygl_ ? mygl_->readPixels() : osmesa_->readPixels()};
    }

private:
    std::unique_ptr<mygl::Context> mygl_;
    std::unique_ptr<reference::OsmesaContext> osmesa_;
};

// Child mode: time one variant in its environment (already set), with the default methods if
// it is MyGL, and print the times.
int runWorker(const std::string& backend, const std::string& sceneName, int width, int height, int repetitions,
              const std::string& framePath) {
    const scenes::Scene* scene = scenes::findScene(sceneName);
    if (!scene || (backend != "osmesa" && backend != "mygl")) return 2;
    Target target(Variant{"", backend == "osmesa", {}, ""}, width, height);
    target.drawFrame(*scene, width, height);  // warm-up: shader compilation
    for (int i = 0; i < repetitions; ++i) std::printf("%f\n", target.drawFrame(*scene, width, height));
    reference::writePng(framePath, target.frame(width, height));
    return 0;
}

Timing runInChild(const char* self, const Variant& v, const std::string& scene, int width, int height,
                  int repetitions) {
    // One file per process: benchmark runs may overlap (tests run in parallel).
    const std::string framePath =
        (std::filesystem::temp_directory_path() / ("mygl-bench-frame-" + std::to_string(getpid()) + ".png")).string();
    const std::string backend = v.isReference ? "osmesa" : "mygl";
    const std::string command = "env " + v.environment + " '" + std::string(self) + "' --worker " + backend + " " +
                                scene + " " + std::to_string(width) + " " + std::to_string(height) + " " +
                                std::to_string(repetitions) + " '" + framePath + "'";
    Timing timing;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return timing;
    double ms = 0;
    while (std::fscanf(pipe, "%lf", &ms) == 1) timing.ms.push_back(ms);
    if (pclose(pipe) == 0) timing.frame = reference::readPng(framePath);
    std::filesystem::remove(framePath);
    return timing;
}

struct Row {
    std::string scene, size, variant;
    bool isReference;
    double median, min, max, ratio, ratioToBest;
    long long differing, differingMoreThan1;
};

// llvmpipe allocates megabytes per frame and frees them; glibc then gives the memory back to
// the kernel and the next frame faults it in again. On a virtual machine where a page fault is
// slow, that made llvmpipe's torus at 640x480 take 30+ ms a frame instead of 6-8, and its 100k
// tiny triangles 135 ms instead of 44. Keeping freed memory in the process measures llvmpipe at
// its best; MyGL allocates nothing per frame, so it is unaffected.
void keepFreedMemory() {
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 64 << 20);
}

}  // namespace

int main(int argc, char** argv) {
    keepFreedMemory();
    if (argc == 8 && std::string(argv[1]) == "--worker")
        return runWorker(argv[2], argv[3], std::atoi(argv[4]), std::atoi(argv[5]), std::atoi(argv[6]), argv[7]);
    bool quick = false;
    std::string out = "bench";
    std::vector<std::string> onlyScenes, onlyVariants;  // empty: all
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--quick")
            quick = true;
        else if (arg == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (arg == "--scene" && i + 1 < argc)
            onlyScenes.push_back(argv[++i]);
        else if (arg == "--variant" && i + 1 < argc)
            onlyVariants.push_back(argv[++i]);
        else {
            std::fprintf(stderr,
                         "usage: mygl-bench [--quick] [--out DIR] [--scene NAME]... [--variant NAME]...\n"
                         "  (llvmpipe is always run: the ratios are to it)\n");
            return 2;
        }
    }
    const auto selected = [](const std::vector<std::string>& only, const std::string& name) {
        return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
    };
    const int repetitions = quick ? 3 : 7;
    std::vector<std::pair<int, int>> sizes{{640, 480}};
    if (!quick) sizes.push_back({1920, 1080});
    std::filesystem::create_directories(out);
    std::vector<Row> rows;
    for (const auto& [width, height] : sizes) {
        for (const char* sceneName : kScenes) {
            if (!selected(onlyScenes, sceneName)) continue;
            const scenes::Scene& scene = *scenes::findScene(sceneName);
            std::vector<Variant> all = variants();
            const std::size_t llvmpipe = 5;
            for (std::size_t v = 0; v < all.size(); ++v) {
                if (v != llvmpipe && !selected(onlyVariants, all[v].name)) all[v].name.clear();  // skipped
            }
            std::vector<Timing> timings(all.size());
            std::vector<std::unique_ptr<Target>> targets(all.size());
            for (std::size_t v = 0; v < all.size(); ++v) {
                if (all[v].name.empty() || !all[v].environment.empty()) continue;
                targets[v] = std::make_unique<Target>(all[v], width, height);
                targets[v]->drawFrame(scene, width, height);  // warm-up
            }
            // In-process variants alternate, so that the machine's drift falls on all of them
            // alike. Each draws an untimed frame before its timed one: the frame measured is the
            // steady state of a program that renders continuously, not the first frame after
            // five other renderers have emptied the caches.
            for (int rep = 0; rep < repetitions; ++rep) {
                std::fprintf(stderr, "\r%dx%d %-12s repetition %d/%d", width, height, sceneName, rep + 1, repetitions);
                for (std::size_t v = 0; v < all.size(); ++v) {
                    if (!targets[v]) continue;
                    targets[v]->drawFrame(scene, width, height);
                    timings[v].ms.push_back(targets[v]->drawFrame(scene, width, height));
                }
            }
            for (std::size_t v = 0; v < all.size(); ++v) {
                if (targets[v])
                    timings[v].frame = targets[v]->frame(width, height);
                else if (!all[v].name.empty())
                    timings[v] = runInChild(argv[0], all[v], sceneName, width, height, repetitions);
            }
            std::fprintf(stderr, "\r%60s\r", "");
            // llvmpipe has slow phases on a shared machine: its best frame is quoted too.
            const double referenceMedian = timings[llvmpipe].median();
            const double referenceBest = *std::min_element(timings[llvmpipe].ms.begin(), timings[llvmpipe].ms.end());
            for (std::size_t v = 0; v < all.size(); ++v) {
                if (timings[v].ms.empty()) continue;
                const auto [lo, hi] = std::minmax_element(timings[v].ms.begin(), timings[v].ms.end());
                const reference::Comparison c = reference::compareImages(timings[v].frame, timings[llvmpipe].frame);
                rows.push_back({sceneName, std::to_string(width) + "x" + std::to_string(height), all[v].name,
                                all[v].isReference, timings[v].median(), *lo, *hi,
                                timings[v].median() / referenceMedian, timings[v].median() / referenceBest, c.differing,
                                c.differingMoreThan1});
                const Row& r = rows.back();
                std::printf(
                    "%-12s %-9s %-26s %9.2f ms  (%.2f-%.2f)  x%.2f of llvmpipe (x%.2f of its best)  differing %lld "
                    "(>1: %lld)\n",
                    r.scene.c_str(), r.size.c_str(), r.variant.c_str(), r.median, r.min, r.max, r.ratio, r.ratioToBest,
                    r.differing, r.differingMoreThan1);
            }
        }
    }
    std::ofstream csv(out + "/bench.csv");
    csv << "scene,size,variant,reference,median_ms,min_ms,max_ms,ratio_to_llvmpipe,ratio_to_llvmpipe_best,differing,"
           "differing_gt1\n";
    std::ofstream md(out + "/bench.md");
    md << "| scene | size | variant | median ms | min-max ms | x llvmpipe | x llvmpipe's best | differing | >1 |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        csv << r.scene << ',' << r.size << ',' << r.variant << ',' << r.isReference << ',' << r.median << ',' << r.min
            << ',' << r.max << ',' << r.ratio << ',' << r.ratioToBest << ',' << r.differing << ','
            << r.differingMoreThan1 << '\n';
        char line[256];
        std::snprintf(line, sizeof line, "| %s | %s | %s | %.2f | %.2f-%.2f | %.2f | %.2f | %lld | %lld |\n",
                      r.scene.c_str(), r.size.c_str(), r.variant.c_str(), r.median, r.min, r.max, r.ratio,
                      r.ratioToBest, r.differing, r.differingMoreThan1);
        md << line;
    }
    csv.close();
    const std::string plot =
        std::string(MYGL_PYTHON) + " '" + MYGL_PLOT_SCRIPT + "' '" + out + "/bench.csv' '" + out + "/bench.png'";
    const bool charted = std::system(plot.c_str()) == 0;
    std::printf("wrote %s/bench.csv, %s/bench.md%s\n", out.c_str(), out.c_str(),
                charted ? " and bench.png" : " (no chart: matplotlib missing?)");
    return 0;
}
