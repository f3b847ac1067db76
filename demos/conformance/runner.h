#pragma once
// Renders conformance cases on both backends and compares them under the accuracy contract.
#include <mygl/context.h>
#include <reference/compare.h>
#include <reference/osmesa_context.h>

#include <cstddef>
#include <map>
#include <string>

#include "cases.h"

namespace conformance {

struct Result {
    reference::Comparison comparison;
    long long depthTies = 0;  // differing pixels where both depth buffers agree within one unit
    // The case's observations (Case::observe): how many lines differ, and the first that does.
    std::size_t observations = 0, observationsDiffering = 0;
    std::string firstObservationDifference;
    bool passed =
        false;  // pixels: flat identical but for depth ties, smooth within 1 but for ties; and every observation equal
    reference::Image ours, theirs;
};

// Two contexts reused for every case; each case resets the state it relies on.
class Runner {
public:
    Runner();
    Result run(const Case& c);

private:
    mygl::Context mygl_;
    reference::OsmesaContext osmesa_;
};

// Reason per case name from a file of "name: reason" lines ('#' starts a comment).
std::map<std::string, std::string> readExpectedDifferences(const std::string& path);

}  // namespace conformance
