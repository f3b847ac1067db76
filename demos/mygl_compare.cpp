// mygl-compare: compares two frames saved as PNG (e.g. a MyGL frame and OSMesa's), prints the
// numbers, optionally writes the diff image; exits 1 if a pixel differs by more than --tolerance.
#include <reference/compare.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    std::string ours, theirs, diff;
    int tolerance = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--tolerance" && i + 1 < argc)
            tolerance = std::atoi(argv[++i]);
        else if (arg == "--diff" && i + 1 < argc)
            diff = argv[++i];
        else if (ours.empty())
            ours = arg;
        else if (theirs.empty())
            theirs = arg;
        else
            ours.clear(), theirs.clear(), i = argc;
    }
    if (ours.empty() || theirs.empty()) {
        std::fprintf(stderr, "usage: mygl-compare OURS.png REFERENCE.png [--diff DIFF.png] [--tolerance N]\n");
        return 2;
    }
    try {
        const reference::Image a = reference::readPng(ours), b = reference::readPng(theirs);
        const reference::Comparison c = reference::compareImages(a, b);
        if (!diff.empty()) reference::writePng(diff, reference::diffImage(a, b));
        std::printf("%s\n", reference::toString(c).c_str());
        return c.maxChannelDifference > tolerance ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mygl-compare: %s\n", e.what());
        return 2;
    }
}
