// Every demo scene rendered live by MyGL and by OSMesa in the test, compared pixel by pixel
// under the accuracy contract (../shared/DESIGN.md section 4). Never against stored images.
#include <gtest/gtest.h>

#include <reference/compare.h>
#include <reference/osmesa_context.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include "render.h"

namespace {

// Scenes drawn with glShadeModel(GL_FLAT): no color is interpolated, so the frames must be
// identical bit for bit. The others interpolate colors (even equal ones, perspective-correct),
// where the reference itself moves by one step between CPUs: within 1 per channel, with exact
// coverage (a coverage difference shows up as a pixel differing by far more than 1).
const std::set<std::string> kFlatScenes = {
    "cube",
    "two-cubes",
    "two-cubes-nodepth",
    "concave-hexahedron",
    "concave-hexahedron-nodepth",
    "xmutual",
    "xmutual-nodepth",
    "polygon5",
    "modes-flat",
    "wireframe-cube",
    "bench-draw-pixels",
};

struct Case {
    const scenes::Scene* scene;
    int frame;
};

std::vector<Case> cases() {
    std::vector<Case> all;
    for (const scenes::Scene& scene : scenes::allScenes()) {
        all.push_back({&scene, 0});
        if (scene.name == "cube" || scene.name == "wireframe-cube")
            for (int frame : {3, 11, 29}) all.push_back({&scene, frame});
    }
    return all;
}

class SceneConformance : public testing::TestWithParam<Case> {};

void writeFailureImages(const std::string& name, const reference::Image& ours, const reference::Image& theirs) {
    const std::filesystem::path dir = MYGL_FAILURE_DIR;
    std::filesystem::create_directories(dir);
    reference::writePng((dir / (name + "-mygl.png")).string(), ours);
    reference::writePng((dir / (name + "-osmesa.png")).string(), theirs);
    reference::writePng((dir / (name + "-diff.png")).string(), reference::diffImage(ours, theirs));
}

TEST_P(SceneConformance, MatchesOsmesa) {
    const auto [scene, frame] = GetParam();
    for (const auto& [width, height] : {std::pair{320, 240}, std::pair{173, 97}}) {
        const scenes::Frame oursFrame = scenes::render(scenes::Backend::MyGL, *scene, width, height, frame);
        const scenes::Frame theirsFrame = scenes::render(scenes::Backend::OSMesa, *scene, width, height, frame);
        const auto& ours = oursFrame.image;
        const auto& theirs = theirsFrame.image;
        const reference::Comparison c = reference::compareImages(ours, theirs);
        const bool flat = kFlatScenes.contains(scene->name);
        const long long ties = reference::depthTies(ours, theirs, oursFrame.depth, theirsFrame.depth, flat ? 0 : 1);
        const bool pass = (flat ? c.differing : c.differingMoreThan1) - ties == 0;
        if (!pass)
            writeFailureImages(scene->name + "-" + std::to_string(frame) + "-" + std::to_string(width), ours, theirs);
        EXPECT_TRUE(pass) << scene->name << " frame " << frame << " at " << width << "x" << height << ": "
                          << reference::toString(c) << " depth-ties=" << ties
                          << (flat ? " (bit-exact required)" : " (within 1 required)") << "; images in "
                          << MYGL_FAILURE_DIR;
        // Stricter than DESIGN.md 4 allows, because it holds: the depth values themselves are the
        // reference's (its plane setup order, vertex stage and clipper arithmetic are followed).
        EXPECT_TRUE(oursFrame.depth == theirsFrame.depth)
            << scene->name << " frame " << frame << ": depth buffers differ";
    }
}

std::string caseName(const testing::TestParamInfo<Case>& info) {
    std::string name = info.param.scene->name + "_frame" + std::to_string(info.param.frame);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(AllScenes, SceneConformance, testing::ValuesIn(cases()), caseName);

}  // namespace

// Frames drawn one after the other on the same contexts, as a program draws them: what a frame
// leaves behind (tiles known to hold the clear values, queued work) must not show in the next.
// Scenes with triangles, lines drawn at once, wireframe and animation, each alternating with a
// scene of another kind on the same context.
TEST(SceneConformance, ConsecutiveFramesOnOneContextMatchOsmesa) {
    constexpr int kWidth = 320, kHeight = 240;
    mygl::Context ours(kWidth, kHeight);
    reference::OsmesaContext theirs(kWidth, kHeight);
    const char* sequence[] = {"bench-gears", "bench-gears", "lines-points", "bench-gears", "wireframe-cube",
                              "cube",        "bench-torus", "bench-torus",  "cube"};
    int frame = 0;
    for (const char* name : sequence) {
        const scenes::Scene* scene = scenes::findScene(name);
        ASSERT_NE(scene, nullptr) << name;
        ours.makeCurrent();
        scene->draw(kWidth, kHeight, frame);
        reference::Image oursImage{kWidth, kHeight, ours.readPixels()};
        const std::vector<std::uint32_t> oursDepth = scenes::readDepth(kWidth, kHeight);
        theirs.makeCurrent();
        scene->draw(kWidth, kHeight, frame);
        reference::Image theirsImage{kWidth, kHeight, theirs.readPixels()};
        const std::vector<std::uint32_t> theirsDepth = scenes::readDepth(kWidth, kHeight);
        const reference::Comparison c = reference::compareImages(oursImage, theirsImage);
        EXPECT_EQ(c.differing, 0) << name << " frame " << frame << ": " << reference::toString(c);
        EXPECT_TRUE(oursDepth == theirsDepth) << name << " frame " << frame << ": depth buffers differ";
        ++frame;
    }
}
