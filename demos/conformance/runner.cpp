#include "runner.h"

#include <glad/gl.h>

#include <algorithm>
#include <fstream>
#include <vector>

#include "scene.h"

namespace conformance {

Runner::Runner() : mygl_(kWidth, kHeight), osmesa_(kWidth, kHeight) {}

Result Runner::run(const Case& c) {
    Result result;
    Observations ours, theirs;
    mygl_.makeCurrent();
    c.draw(kWidth, kHeight);
    if (c.observe) c.observe(ours);
    result.ours = {kWidth, kHeight, mygl_.readPixels()};
    const auto oursDepth = scenes::readDepth(kWidth, kHeight);
    osmesa_.makeCurrent();
    c.draw(kWidth, kHeight);
    if (c.observe) c.observe(theirs);
    result.theirs = {kWidth, kHeight, osmesa_.readPixels()};
    const auto theirsDepth = scenes::readDepth(kWidth, kHeight);
    result.comparison = reference::compareImages(result.ours, result.theirs);
    const int tolerance = c.flat ? 0 : 1;
    result.depthTies = reference::depthTies(result.ours, result.theirs, oursDepth, theirsDepth, tolerance);
    const long long over = c.flat ? result.comparison.differing : result.comparison.differingMoreThan1;
    result.observations = std::max(ours.lines().size(), theirs.lines().size());
    for (std::size_t i = 0; i < result.observations; ++i) {
        const bool both = i < ours.lines().size() && i < theirs.lines().size();
        result.observationsDiffering += !both || ours.lines()[i] != theirs.lines()[i];
    }
    result.firstObservationDifference = firstDifference(ours.lines(), theirs.lines());
    result.passed = over - result.depthTies == 0 && result.observationsDiffering == 0;
    return result;
}

std::map<std::string, std::string> readExpectedDifferences(const std::string& path) {
    std::map<std::string, std::string> expected;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const auto colon = line.find(':');
        expected[line.substr(0, colon)] = colon == std::string::npos ? "" : line.substr(colon + 1);
    }
    return expected;
}

}  // namespace conformance
